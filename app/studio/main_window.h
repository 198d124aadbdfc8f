// The studio's main window: menus, toolbar, status bar, the viewport in the centre and the
// scene / properties docks. It owns the Document and the RenderController; everything it shows
// comes from them. GUI thread only.
#pragma once

#include "final_render.h"
#include "model_import.h"

#include "inlay/modeling/core.h"

#include <QElapsedTimer>
#include <QList>
#include <QMainWindow>
#include <QPointer>
#include <QTemporaryDir>

#include <functional>
#include <memory>
#include <optional>

class QAction;
class QLabel;
class QMenu;
class QMessageBox;
class QProgressDialog;
class QThread;
class QTimer;
class QToolBar;

namespace inlay::studio {

class Autosaver;
class Document;
class StepsDock;
class LayersDock;
class LogDock;
class PropertiesDock;
class ResponseDock;
class RenderController;
class SceneTreeDock;
class StatusBar;
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
  LogDock* logDock() const { return logDock_; }
  Autosaver* autosaver() const { return autosaver_; }
  QMenu* fileMenu() const { return fileMenu_; }
  QMenu* toolsMenu() const { return toolsMenu_; }
  QMenu* editMenu() const { return editMenu_; }
  QAction* undoAction() const { return undoAct_; }
  QAction* redoAction() const { return redoAct_; }
  // The action that picks a tool of the viewport (Viewport::Tool as int).
  QAction* toolAction(int tool) const;
  QAction* acceptBoxAction() const { return acceptBoxAct_; }

  // If a previous run left a recovery file: interactive, asks (non-blocking) whether to
  // restore it; returns true when there was one. Non-interactive: only returns whether.
  bool offerRecovery();
  // Restores the recovery file now (see Autosaver); false when there is none or it is unreadable.
  bool restoreRecovery();

  // Opens a scene file (.json) or a bare photo (anything else). Problems are shown in a
  // (non-blocking) message box; returns false when nothing was opened. While a final render
  // runs, an interactive window first asks (see settleFinalRender) and opens once the render
  // is cancelled; false meanwhile.
  bool openPath(const QString& path);
  // The bundled example: exampleScenePath(), or the copy embedded in the program.
  bool openExample();
  // The copy embedded in the program (:/example/), unpacked to a temporary folder that lives
  // as long as the window.
  bool openEmbeddedExample();
  // Writes the scene file; returns false (after telling the user) on failure.
  bool saveTo(const QString& path);
  // Writes the newest composite (format by extension: .png/.jpg/.tif 8-bit sRGB, .exr linear):
  // the final render while the viewport shows it, else the preview's;
  // returns false (after telling the user) on failure.
  bool exportComposite(const QString& path);
  // Writes the layer the viewport shows (8-bit sRGB: .png, .jpg, .tif) atomically; returns
  // false (after telling the user) when it does not exist yet or cannot be written.
  bool exportShownLayer(const QString& path);
  // Writes the reconstructed scene (room with its albedo textures, lights, camera, objects where
  // they stand now) as glTF 2.0 (.gltf with its .bin and textures beside it, or one .glb);
  // returns false (after telling the user) when the scene is not prepared or cannot be written.
  bool exportSceneGltf(const QString& path);
  // Insert Model…: reads the model file on a worker thread, then inserts it standing at
  // `dropPx` (image pixels; on the surface under it, or straight below it) or, without one, in
  // the middle of the visible floor. While the scene is being prepared the model waits and goes
  // in once it is ready. A refusal (unreadable, too large, flat, no place to stand) is a dialog
  // naming the file and the reason. Returns false when refused at once (not a model file, no
  // photo open).
  bool insertModelFile(const QString& path, const std::optional<Vec2>& dropPx = std::nullopt);
  // Model files being read or waiting for the scene (the tests wait for 0).
  int pendingModelCount() const { return int(loaders_.size() + waitingModels_.size()); }
  // The last refusal of insertModelFile (for tests; cleared by the next call).
  QString lastModelError() const { return lastModelError_; }
  QAction* insertModelAction() const { return insertModelAct_; }
  QAction* duplicateAction() const { return duplicateAct_; }
  QAction* hideAction() const { return hideAct_; }
  QAction* renameAction() const { return renameAct_; }
  QAction* deleteAction() const { return deleteAct_; }
  QMenu* recentMenu() const { return recentMenu_; }
  // Render Final Image…: renders the scene as it is now at the photo's full resolution to its
  // noise target on a thread of its own (the preview pauses meanwhile), with a progress dialog
  // whose Cancel stops it, then writes `path` (PNG, JPEG, TIFF or EXR by its extension)
  // atomically. Returns false (after telling the user) when it cannot start: nothing prepared,
  // a render already running, an unknown extension or a missing folder. finalImageFinished
  // follows every start. `maxSpp` > 0 caps the samples per pixel (tests, drafts).
  bool renderFinalImage(const QString& path, int maxSpp = 0);
  // A final render under way while the window closes or another scene opens: true when there
  // is none (or it is already stopping) and the caller goes on now. Non-interactive: cancels it
  // and returns true. Interactive: opens a question (objectName "finalRenderQuestion"; buttons
  // `proceedText`, e.g. "Cancel the Render and Close", and "Keep Rendering") and returns false;
  // `proceed` runs once the user chose to cancel the render.
  bool settleFinalRender(const QString& proceedText, const std::function<void()>& proceed);
  // The final render under way (null when none).
  FinalRender* finalRender() const { return finalRender_; }
  QAction* renderFinalAction() const { return renderFinalAct_; }
  QAction* splitAction() const { return splitAct_; }
  QAction* exportAction() const { return exportAct_; }
  QAction* quitAction() const { return quitAct_; }
  StepsDock* stepsDock() const { return stepsDock_; }
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
  QString askImagePath(const QString& title, const QString& suggestion);
  // The save dialog's file types for a composite: PNG, JPEG, TIFF, linear EXR (in that order).
  static QStringList compositeImageFilters();
  void exportLayerDialog();
  void exportSceneGltfDialog();
  void renderFinalDialog();
  void about();
  // Inserts a builtin mesh ("builtin:sphere", "builtin:cube") standing in the middle of the
  // visible floor; false (with the reason in the status bar) when there is no such place.
  bool insertBuiltin(const QString& mesh);
  void deleteSelected();
  void insertModelDialog();
  void duplicateSelected();
  void toggleSelectedHidden();
  void renameSelected();

 Q_SIGNALS:
  // A final render ended: ok when its file was written; message: what was written or why not.
  void finalImageFinished(bool ok, const QString& message);

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
  void showPrepareProgress();
  void updateTitle();
  void showError(const QString& title, const QString& text);
  void addRecentFile(const QString& path, const char* key = "recentFiles");
  // A model file read by the worker: inserted now, kept until the scene is ready, or refused.
  void onModelLoaded(const ModelLoadResult& result, const std::optional<Vec2>& dropPx);
  std::optional<QString> ownSizeMisfit(const ModelImport& model, double heightM) const;
  bool placeModel(const ModelImport& model, std::optional<Vec2> dropPx);
  void refuseModel(const QString& text);
  void rebuildRecentMenu();
  bool maybeSave();
  void createStepsDock();
  void onFinalRenderFinished(bool ok, const QString& message);
  // The finished final image in the viewport (and the status bar says so) until the next edit.
  void showFinalImage(const FinalRender& render);
  void showFinalTexts();
  void fitStatusFields();
  void dropFinalImage();

  Document* document_;
  RenderController* renderer_;
  Viewport* viewport_;
  SceneTreeDock* sceneDock_;
  PropertiesDock* propertiesDock_;
  LayersDock* layersDock_;
  ResponseDock* responseDock_ = nullptr;
  LogDock* logDock_ = nullptr;  // each preparation's stages and warnings
  StepsDock* stepsDock_ = nullptr;
  QPointer<FinalRender> finalRender_;
  QPointer<QProgressDialog> finalProgress_;
  QPointer<QMessageBox> finalQuestion_;        // "cancel the final render?" while it is open
  std::shared_ptr<const ImageF> finalLinear_;  // the shown final image (Export Composite writes it)
  FinalRender::Progress finalFigures_;         // the shown final image's figures
  QString finalShownText_;  // the status line while the final image is shown (empty: not shown)
  QString finalFile_;       // the shown final image's file name
  Autosaver* autosaver_;
  bool reportFailure_ = true;  // a failed preparation after an open gets a dialog
  QPointer<QProgressDialog> progress_;
  QTimer* prepareTicker_ = nullptr;  // the preparation dialog's seconds
  QElapsedTimer prepareClock_;
  QString prepareStage_;  // the stage the preparation reported last, and its fraction
  double prepareFraction_ = 0;
  std::unique_ptr<QTemporaryDir> exampleCopy_;  // the embedded example, unpacked
  bool interactive_ = true;
  // Insert Model…: the threads reading model files, and models read while the scene prepared.
  QList<QThread*> loaders_;
  struct WaitingModel {
    ModelImport model;
    std::optional<Vec2> dropPx;
  };
  std::vector<WaitingModel> waitingModels_;
  QString lastModelError_;

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
  QAction* renderFinalAct_ = nullptr;
  QAction* splitAct_ = nullptr;
  QAction* quitAct_ = nullptr;
  QAction* undoAct_ = nullptr;
  QAction* redoAct_ = nullptr;
  QAction* insertSphereAct_ = nullptr;
  QAction* insertCubeAct_ = nullptr;
  QAction* insertModelAct_ = nullptr;
  QAction* duplicateAct_ = nullptr;
  QAction* hideAct_ = nullptr;
  QAction* renameAct_ = nullptr;
  QAction* deleteAct_ = nullptr;
  QAction* zoomInAct_ = nullptr;
  QAction* zoomOutAct_ = nullptr;
  QAction* fitAct_ = nullptr;
  QAction* beforeAct_ = nullptr;
  QAction* denoiseAct_ = nullptr;  // View > Denoise Preview (QSettings "denoisePreview")
  QAction* aboutAct_ = nullptr;

  StatusBar* statusBar_ = nullptr;
  QLabel* sppLabel_ = nullptr;
  QLabel* rateLabel_ = nullptr;
  QLabel* errorLabel_ = nullptr;
  QLabel* timeLabel_ = nullptr;
  QLabel* zoomLabel_ = nullptr;
};

}  // namespace inlay::studio
