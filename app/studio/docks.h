// The two docks beside the viewport. Both rebuild their contents from the Document's state when
// it announces a change, and edit it only through its API (undoable commands).
//   SceneTreeDock: the room, the marks (lights, shafts, surfaces, occluders) and the objects;
//     choosing an object or a mark selects it in the document (and so in the viewport).
//   LayersDock: which image the viewport shows (composite, photo, albedo, direct light, with and
//     without objects, mask, difference).
//   PropertiesDock: name, shown or hidden, size (width x depth x height in metres), height_m,
//     yaw_deg, material preset and albedo colour of the selected object, every field labelled;
//     the height new models get when their file does not state their unit; below, a real surface of the room (floor, walls, ceiling, table tops) and its material
//     (matte, glossy with a roughness, mirror: room.materials).
// Each retranslates its texts on QEvent::LanguageChange.
// GUI thread only.
#pragma once

#include <QDockWidget>

#include <optional>
#include <utility>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QListWidget;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTreeWidget;

namespace inlay::studio {

class Document;
class Viewport;
struct ChangeEvent;

class SceneTreeDock : public QDockWidget {
  Q_OBJECT

 public:
  explicit SceneTreeDock(Document* document, QWidget* parent = nullptr);
  QTreeWidget* tree() const { return tree_; }
  // Opens the in-place editor on object `index`'s name (shows the dock); false if no such item.
  bool editName(int index);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void rebuild();
  void syncSelection();
  void onDocumentChanged(const ChangeEvent& event);

  Document* document_;
  QTreeWidget* tree_;
  bool updating_ = false;
};

class LayersDock : public QDockWidget {
  Q_OBJECT

 public:
  explicit LayersDock(Viewport* viewport, QWidget* parent = nullptr);
  QListWidget* list() const { return list_; }

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  QListWidget* list_;
};

class PropertiesDock : public QDockWidget {
  Q_OBJECT

 public:
  explicit PropertiesDock(Document* document, QWidget* parent = nullptr);
  QLineEdit* nameBox() const { return name_; }
  QCheckBox* shownBox() const { return shown_; }
  QLabel* sizeLabel() const { return size_; }
  QDoubleSpinBox* newModelHeightBox() const { return newModelHeight_; }
  QDoubleSpinBox* heightBox() const { return height_; }
  QDoubleSpinBox* yawBox() const { return yaw_; }
  QComboBox* presetBox() const { return preset_; }
  // The room surface shown and its material: index 0 matte, 1 glossy, 2 mirror.
  QComboBox* roomSurfaceBox() const { return roomSurface_; }
  QComboBox* roomPresetBox() const { return roomPreset_; }
  QDoubleSpinBox* roomRoughnessBox() const { return roomRoughness_; }

 Q_SIGNALS:
  void statusMessage(const QString& message);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void refresh();
  void refreshRoom();
  void editRoomMaterial();
  void editHeight(double heightM);
  void editYaw(double yawDeg);
  void editPreset(int comboIndex);
  void pickAlbedo();
  void report(bool ok, const QString& reason);

  Document* document_;
  QLabel* title_;
  QLineEdit* name_;
  QCheckBox* shown_;
  QLabel* size_;
  QLabel* base_;
  QDoubleSpinBox* height_;
  QDoubleSpinBox* yaw_;
  QComboBox* preset_;
  QPushButton* albedo_;
  QLabel* roomTitle_;
  QComboBox* roomSurface_;
  QComboBox* roomPreset_;
  QDoubleSpinBox* roomRoughness_;
  QLabel* newModelsTitle_;
  QDoubleSpinBox* newModelHeight_;
};

// The height (metres) a model gets when its file does not state its unit, or states an absurd
// one: the Properties dock's "New models" field, kept in the settings.
double defaultModelHeightM();
void setDefaultModelHeightM(double metres);

}  // namespace inlay::studio
