// The studio's main window: menus, toolbar, status bar, the viewport in the centre and the
// scene / properties docks. It owns the Document and the RenderController; everything it shows
// comes from them. GUI thread only.
#pragma once

#include <QMainWindow>
#include <QPointer>
#include <QTemporaryDir>

#include <memory>

class QAction;
class QLabel;
class QMenu;
class QProgressDialog;
class QToolBar;

namespace inlay::studio {

class Autosaver;
class Document;
class LayersDock;
class PropertiesDock;
class ResponseDock;
class RenderController;
class SceneTreeDock;
class Viewport;
struct ChangeEvent;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  Document* document() const { return document_; }
  RenderController* renderer() const { return renderer_; }
  Viewport* viewport() const { return viewport_; }
  SceneTreeDock* sceneDock() const { return sceneDock_; }
  PropertiesDock* propertiesDock() const { return propertiesDock_; }
  LayersDock* layersDock() const { return layersDock_; }
  Autosaver* autosaver() const { return autosaver_; }
  QMenu* fileMenu() const { return fileMenu_; }
  QMenu* toolsMenu() const { return toolsMenu_; }
  QMenu* editMenu() const { return editMenu_; }
  QAction* undoAction() const { return undoAct_; }
  // The action that picks a tool of the viewport (Viewport::Tool as int).
  QAction* toolAction(int tool) const;
  QAction* acceptBoxAction() const { return acceptBoxAct_; }

  // If a previous run left a recovery file: interactive, asks (non-blocking) whether to
  // restore it; returns true when there was one. Non-interactive: only returns whether.
  bool offerRecovery();
  // Restores the recovery file now (see Autosaver); false when there is none or it is unreadable.
  bool restoreRecovery();

  // Opens a scene file (.json) or a bare photo (anything else). Problems are shown in a
  // (non-blocking) message box; returns false when nothing was opened.
  bool openPath(const QString& path);
  // The bundled example: exampleScenePath(), or the copy embedded in the program.
  bool openExample();
  // The copy embedded in the program (:/example/), unpacked to a temporary folder that lives
  // as long as the window.
  bool openEmbeddedExample();
  // Writes the scene file; returns false (after telling the user) on failure.
  bool saveTo(const QString& path);
  // Writes the newest composite (format by extension: .png/.jpg/.tif 8-bit sRGB, .exr linear);
  // returns false (after telling the user) on failure.
  bool exportComposite(const QString& path);
  // Writes the layer the viewport shows (8-bit sRGB: .png, .jpg, .tif) atomically; returns
  // false (after telling the user) when it does not exist yet or cannot be written.
  bool exportShownLayer(const QString& path);
  // Writes the reconstructed scene (room with its albedo textures, lights, camera, objects where
  // they stand now) as glTF 2.0 (.gltf with its .bin and textures beside it, or one .glb);
  // returns false (after telling the user) when the scene is not prepared or cannot be written.
  bool exportSceneGltf(const QString& path);
  // Shows modal questions (unsaved changes, errors)? Off for --screenshot and tests.
  void setInteractive(bool interactive) { interactive_ = interactive; }

 public Q_SLOTS:
  // Stores the language ("" = the system's, "en", "de", "fr") and installs its translators;
  // every open window retranslates at once (QEvent::LanguageChange).
  void setLanguage(const QString& code);
  void openSceneDialog();
  void openPhotoDialog();
  bool save();
  bool saveAsDialog();
  void exportCompositeDialog();
  void exportLayerDialog();
  void exportSceneGltfDialog();
  void about();
  // Inserts a builtin mesh ("builtin:sphere", "builtin:cube") standing in the middle of the
  // visible floor; false (with the reason in the status bar) when there is no such place.
  bool insertBuiltin(const QString& mesh);
  void deleteSelected();

 protected:
  void closeEvent(QCloseEvent* event) override;
  void changeEvent(QEvent* event) override;
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void createActions();
  void createMenus();
  void retranslate();
  void updateUndoActions();
  void onDocumentChanged(const ChangeEvent& event);
  void onFrame();
  void updateTitle();
  void showError(const QString& title, const QString& text);
  void addRecentFile(const QString& path);
  void rebuildRecentMenu();
  bool maybeSave();

  Document* document_;
  RenderController* renderer_;
  Viewport* viewport_;
  SceneTreeDock* sceneDock_;
  PropertiesDock* propertiesDock_;
  LayersDock* layersDock_;
  ResponseDock* responseDock_ = nullptr;
  Autosaver* autosaver_;
  bool reportFailure_ = true;  // a failed preparation after an open gets a dialog
  QPointer<QProgressDialog> progress_;
  std::unique_ptr<QTemporaryDir> exampleCopy_;  // the embedded example, unpacked
  bool interactive_ = true;

  QMenu* fileMenu_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QMenu* toolsMenu_ = nullptr;
  QMenu* editMenu_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* languageMenu_ = nullptr;
  QMenu* helpMenu_ = nullptr;
  QToolBar* mainToolBar_ = nullptr;
  QAction* systemLanguageAct_ = nullptr;
  QList<QAction*> toolActs_;
  QAction* acceptBoxAct_ = nullptr;
  QAction* resetBoxAct_ = nullptr;
  QAction* prepareAct_ = nullptr;
  QAction* vanishingAct_ = nullptr;
  QAction* openSceneAct_ = nullptr;
  QAction* openPhotoAct_ = nullptr;
  QAction* openExampleAct_ = nullptr;
  QAction* saveAct_ = nullptr;
  QAction* saveAsAct_ = nullptr;
  QAction* exportAct_ = nullptr;
  QAction* exportLayerAct_ = nullptr;
  QAction* exportGltfAct_ = nullptr;
  QAction* quitAct_ = nullptr;
  QAction* undoAct_ = nullptr;
  QAction* redoAct_ = nullptr;
  QAction* insertSphereAct_ = nullptr;
  QAction* insertCubeAct_ = nullptr;
  QAction* deleteAct_ = nullptr;
  QAction* zoomInAct_ = nullptr;
  QAction* zoomOutAct_ = nullptr;
  QAction* fitAct_ = nullptr;
  QAction* beforeAct_ = nullptr;
  QAction* aboutAct_ = nullptr;

  QLabel* sppLabel_ = nullptr;
  QLabel* rateLabel_ = nullptr;
  QLabel* errorLabel_ = nullptr;
  QLabel* timeLabel_ = nullptr;
  QLabel* zoomLabel_ = nullptr;
};

}  // namespace inlay::studio
