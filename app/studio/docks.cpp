#include "docks.h"

#include "document.h"
#include "render_controller.h"
#include "viewport.h"

#include "model_import.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace inlay::studio {
namespace {

constexpr int kRoleObject = Qt::UserRole + 1;    // object index, or -1
constexpr int kRoleMarkKind = Qt::UserRole + 2;  // MarkKind as int
constexpr int kRoleMarkIndex = Qt::UserRole + 3;

// A dock's body that scrolls when the window is short: it asks for all of its content's size
// (so a tall enough window shows every field, as before) but insists only on a few lines of it.
// Without it, Properties' fields fixed the window's minimum height: 870 to 940 px with the docks
// stacked beside it, more than a 1024 x 768 screen or a 1366 x 768 laptop has (issue #16).
class ScrollingBody : public QScrollArea {
 public:
  ScrollingBody(QWidget* parent, QWidget* body) : QScrollArea(parent) {
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    setWidget(body);
    body->installEventFilter(this);
  }
  QSize sizeHint() const override {
    return widget()->sizeHint() + QSize(verticalScrollBar()->sizeHint().width(), 0);
  }
  QSize minimumSizeHint() const override {
    const QSize body = widget()->minimumSizeHint();
    const int lines = kMinimumLines * fontMetrics().lineSpacing();
    return {body.width() + verticalScrollBar()->sizeHint().width(), std::min(body.height(), lines)};
  }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (watched == widget() && event->type() == QEvent::LayoutRequest) updateGeometry();
    return QScrollArea::eventFilter(watched, event);
  }

 private:
  static constexpr int kMinimumLines = 8;  // about four rows of fields
};

QString meshName(const ObjectKeys& o) {
  if (o.mesh == "builtin:sphere") return SceneTreeDock::tr("sphere");
  if (o.mesh == "builtin:cube") return SceneTreeDock::tr("cube");
  return QFileInfo(QString::fromStdString(o.mesh)).fileName();
}

const char* const kDefaultHeightKey = "insert/defaultModelHeightM";

// A real surface of the room as the user reads it ("floor", "wall_left", "surface_0_top": the
// engine's names, which the scene file's room.materials keys keep).
QString roomSurfaceTitle(const QString& name) {
  static const QRegularExpression marked(QStringLiteral("^surface_(\\d+)_(top|side)$"));
  if (name == QLatin1String("floor")) return PropertiesDock::tr("Floor");
  if (name == QLatin1String("ceiling")) return PropertiesDock::tr("Ceiling");
  if (name == QLatin1String("wall_left")) return PropertiesDock::tr("Left wall");
  if (name == QLatin1String("wall_right")) return PropertiesDock::tr("Right wall");
  if (name == QLatin1String("wall_back")) return PropertiesDock::tr("Back wall");
  if (name == QLatin1String("wall_rear")) return PropertiesDock::tr("Wall behind the camera");
  const QRegularExpressionMatch m = marked.match(name);
  if (!m.hasMatch()) return name;
  const int number = m.captured(1).toInt() + 1;  // as the Scene dock counts the surfaces
  return m.captured(2) == QLatin1String("top") ? PropertiesDock::tr("Surface %1, top").arg(number)
                                               : PropertiesDock::tr("Surface %1, sides").arg(number);
}

// A marked surface's kind (scene file: "extrusion", "box", "stairs") as the Scene dock shows it.
QString surfaceKindTitle(const std::string& kind) {
  if (kind == "extrusion") return SceneTreeDock::tr("table top or step");
  if (kind == "box") return SceneTreeDock::tr("box");
  if (kind == "stairs") return SceneTreeDock::tr("stairs");
  return QString::fromStdString(kind);
}

QColor displayColour(const Vec3& linear) {
  auto enc = [](double v) { return int(srgbCode8(float(v))); };
  return QColor(enc(linear.x()), enc(linear.y()), enc(linear.z()));
}

}  // namespace

// ---------------------------------------------------------------- SceneTreeDock

SceneTreeDock::SceneTreeDock(Document* document, QWidget* parent)
    : QDockWidget(parent), document_(document), tree_(new QTreeWidget(this)) {
  setObjectName(QStringLiteral("sceneDock"));
  tree_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  tree_->setRootIsDecorated(true);
  setWidget(tree_);
  connect(document_, &Document::changed, this, &SceneTreeDock::onDocumentChanged);
  tree_->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::DoubleClicked);
  connect(tree_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
    if (updating_ || column != 0 || !item->data(0, kRoleObject).isValid()) return;
    const int index = item->data(0, kRoleObject).toInt();
    if (item->text(0) == document_->objectName(index)) return;
    QString reason;
    // Rebuilt by the document's change (or put back on refusal).
    if (!document_->renameObject(index, item->text(0), &reason)) rebuild();
  });
  connect(tree_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (updating_ || !item) return;
    const QVariant v = item->data(0, kRoleObject);
    if (v.isValid()) document_->setSelectedObject(v.toInt());
    if (item->data(0, kRoleMarkKind).isValid())
      document_->setSelectedMark(MarkRef{MarkKind(item->data(0, kRoleMarkKind).toInt()),
                                         item->data(0, kRoleMarkIndex).toInt()});
  });
  rebuild();
}

void SceneTreeDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) rebuild();
  QDockWidget::changeEvent(event);
}

void SceneTreeDock::onDocumentChanged(const ChangeEvent& event) {
  if (event.has(ChangeEvent::SceneReplaced) || event.has(ChangeEvent::PrepareFinished) ||
      event.has(ChangeEvent::ObjectMaterial) || event.has(ChangeEvent::ObjectPlacement) ||
      event.has(ChangeEvent::ObjectShown) || event.has(ChangeEvent::ObjectsAddedOrRemoved) ||
      event.has(ChangeEvent::Marks))
    rebuild();
  else if (event.has(ChangeEvent::Selection)) syncSelection();
}

void SceneTreeDock::rebuild() {
  updating_ = true;
  setWindowTitle(tr("Scene"));
  tree_->setHeaderLabels({tr("Item"), tr("Details")});
  tree_->clear();
  const SceneDoc& doc = document_->scene();

  auto* room = new QTreeWidgetItem(tree_, {tr("Room")});
  if (const PreparedScene* p = document_->prepared()) {
    const RoomBox& b = p->box;
    room->setText(1, tr("%1 × %2 m, %3 m high")
                         .arg(b.xRightM - b.xLeftM, 0, 'f', 2)
                         .arg(b.zRearM - b.zBackM, 0, 'f', 2)
                         .arg(b.ceilingM, 0, 'f', 2));
  } else {
    room->setText(1, doc.layout.backWallPx ? tr("back wall given") : tr("estimated"));
  }

  auto* lights = new QTreeWidgetItem(tree_, {tr("Lights"), QString::number(doc.lights.size())});
  for (size_t i = 0; i < doc.lights.size(); ++i) {
    const LightKeys& l = doc.lights[i];
    auto* item = new QTreeWidgetItem(
        lights,
        {tr("Light %1").arg(i + 1),
         l.kind == LightKeys::Kind::PolygonPx ? tr("outline on the photo") : tr("rectangle in 3D")});
    item->setData(0, kRoleMarkKind, int(MarkKind::Light));
    item->setData(0, kRoleMarkIndex, int(i));
  }
  // The other marks: one item each, deletable from the Edit menu.
  auto addMarks = [&](const QString& group, size_t count, MarkKind kind, const QString& name,
                      auto details) {
    auto* parent = new QTreeWidgetItem(tree_, {group, QString::number(count)});
    for (size_t i = 0; i < count; ++i) {
      auto* item = new QTreeWidgetItem(parent, {name.arg(i + 1), details(i)});
      item->setData(0, kRoleMarkKind, int(kind));
      item->setData(0, kRoleMarkIndex, int(i));
    }
  };
  addMarks(tr("Shafts"), doc.shafts.size(), MarkKind::Shaft, tr("Shaft %1"),
           [](size_t) { return tr("sunlit patch and its window"); });
  addMarks(tr("Surfaces"), doc.surfaces.size(), MarkKind::Surface, tr("Surface %1"),
           [&](size_t i) { return surfaceKindTitle(doc.surfaces[i].kind); });
  addMarks(tr("Occluders"), doc.occluders.size(), MarkKind::Occluder, tr("Occluder %1"), [&](size_t i) {
    return tr("%1 strokes in front, %2 behind")
        .arg(doc.occluders[i].foregroundScribblesPx.size())
        .arg(doc.occluders[i].backgroundScribblesPx.size());
  });
  auto* objects = new QTreeWidgetItem(tree_, {tr("Objects"), QString::number(doc.objects.size())});
  for (size_t i = 0; i < doc.objects.size(); ++i) {
    const ObjectKeys& o = doc.objects[i];
    const QString details = tr("%1, %2 m").arg(meshName(o)).arg(o.heightM, 0, 'f', 2);
    auto* item = new QTreeWidgetItem(
        objects, {document_->objectName(int(i)), o.hidden ? tr("hidden: %1").arg(details) : details});
    item->setData(0, kRoleObject, int(i));
    item->setFlags(item->flags() | Qt::ItemIsEditable);  // F2 / double click renames
    if (o.hidden) item->setForeground(0, tree_->palette().brush(QPalette::Disabled, QPalette::Text));
    item->setIcon(0, [&] {
      QPixmap swatch(12, 12);
      swatch.fill(displayColour(o.material.albedo));
      return QIcon(swatch);
    }());
  }
  for (QTreeWidgetItemIterator it(tree_); *it; ++it) (*it)->setToolTip(1, (*it)->text(1));
  tree_->expandAll();
  updating_ = false;
  syncSelection();
}

bool SceneTreeDock::editName(int index) {
  for (QTreeWidgetItemIterator it(tree_); *it; ++it)
    if ((*it)->data(0, kRoleObject).isValid() && (*it)->data(0, kRoleObject).toInt() == index) {
      show();
      raise();
      tree_->setCurrentItem(*it);
      tree_->editItem(*it, 0);
      return true;
    }
  return false;
}

// ---------------------------------------------------------------- LayersDock

LayersDock::LayersDock(Viewport* viewport, QWidget* parent)
    : QDockWidget(parent), list_(new QListWidget(this)) {
  setObjectName(QStringLiteral("layersDock"));
  for (int i = 0; i < kLayerCount; ++i) list_->addItem(QString());
  retranslate();
  list_->setCurrentRow(int(viewport->layer()));
  setWidget(list_);
  connect(list_, &QListWidget::currentRowChanged, viewport, [viewport](int row) {
    if (row >= 0 && row < kLayerCount) viewport->setLayer(Layer(row));
  });
}

void LayersDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

void LayersDock::retranslate() {
  setWindowTitle(tr("Layers"));
  const QString names[kLayerCount] = {tr("Composite"),    tr("Photo"),        tr("Albedo"),
                                      tr("Direct light"), tr("With objects"), tr("Without objects"),
                                      tr("Mask"),         tr("Difference")};
  for (int i = 0; i < kLayerCount; ++i) list_->item(i)->setText(names[i]);
}

void SceneTreeDock::syncSelection() {
  updating_ = true;
  const int selected = document_->selectedObject();
  const std::optional<MarkRef> mark = document_->selectedMark();
  QTreeWidgetItem* found = nullptr;
  for (QTreeWidgetItemIterator it(tree_); *it; ++it) {
    if ((*it)->data(0, kRoleObject).isValid() && (*it)->data(0, kRoleObject).toInt() == selected)
      found = *it;
    if (mark && (*it)->data(0, kRoleMarkKind).isValid() &&
        MarkRef{MarkKind((*it)->data(0, kRoleMarkKind).toInt()),
                (*it)->data(0, kRoleMarkIndex).toInt()} == *mark)
      found = *it;
  }
  tree_->setCurrentItem(found);
  if (!found) tree_->clearSelection();
  updating_ = false;
}

// ---------------------------------------------------------------- PropertiesDock

PropertiesDock::PropertiesDock(Document* document, QWidget* parent)
    : QDockWidget(parent), document_(document) {
  setObjectName(QStringLiteral("propertiesDock"));
  auto* panel = new QWidget(this);
  auto* form = new QFormLayout(panel);
  title_ = new QLabel(panel);
  name_ = new QLineEdit(panel);
  shown_ = new QCheckBox(panel);
  size_ = new QLabel(panel);
  size_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  base_ = new QLabel(panel);
  base_->setTextInteractionFlags(Qt::TextSelectableByMouse);

  height_ = new QDoubleSpinBox(panel);
  height_->setRange(0.01, 100.0);
  height_->setDecimals(3);
  height_->setSingleStep(0.05);
  height_->setKeyboardTracking(false);

  yaw_ = new QDoubleSpinBox(panel);
  yaw_->setRange(-360.0, 360.0);
  yaw_->setDecimals(1);
  yaw_->setSingleStep(5.0);
  yaw_->setWrapping(true);
  yaw_->setKeyboardTracking(false);

  preset_ = new QComboBox(panel);
  for (const char* preset :
       {"diffuse", "glossy", "mirror", "metal", "glass", "rough_glass", "emissive", "asset"})
    preset_->addItem(QString(), QString::fromLatin1(preset));
  albedo_ = new QPushButton(panel);

  roomTitle_ = new QLabel(panel);
  roomSurface_ = new QComboBox(panel);
  roomPreset_ = new QComboBox(panel);
  for (const char* preset : {"diffuse", "glossy", "mirror"})
    roomPreset_->addItem(QString(), QString::fromLatin1(preset));
  roomRoughness_ = new QDoubleSpinBox(panel);
  roomRoughness_->setRange(0.0, 1.0);
  roomRoughness_->setDecimals(2);
  roomRoughness_->setSingleStep(0.05);
  roomRoughness_->setKeyboardTracking(false);

  newModelsTitle_ = new QLabel(panel);
  newModelHeight_ = new QDoubleSpinBox(panel);
  newModelHeight_->setRange(kMinPlausibleHeightM, kMaxPlausibleHeightM);
  newModelHeight_->setDecimals(2);
  newModelHeight_->setSingleStep(0.05);
  newModelHeight_->setKeyboardTracking(false);
  newModelHeight_->setValue(defaultModelHeightM());

  // Every field with its own label (QFormLayout makes none for an empty text, and retranslate()
  // needs one to set).
  form->addRow(title_);
  for (QWidget* field :
       {static_cast<QWidget*>(name_), static_cast<QWidget*>(shown_), static_cast<QWidget*>(size_),
        static_cast<QWidget*>(base_), static_cast<QWidget*>(height_), static_cast<QWidget*>(yaw_),
        static_cast<QWidget*>(preset_), static_cast<QWidget*>(albedo_)})
    form->addRow(new QLabel(panel), field);
  form->addRow(roomTitle_);
  for (QWidget* field : {static_cast<QWidget*>(roomSurface_), static_cast<QWidget*>(roomPreset_),
                         static_cast<QWidget*>(roomRoughness_)})
    form->addRow(new QLabel(panel), field);
  form->addRow(newModelsTitle_);
  form->addRow(new QLabel(panel), newModelHeight_);
  for (int row = 0; row < form->rowCount(); ++row)  // a click on a label focuses its field
    if (auto* l = qobject_cast<QLabel*>(form->itemAt(row, QFormLayout::LabelRole)
                                            ? form->itemAt(row, QFormLayout::LabelRole)->widget()
                                            : nullptr))
      if (QLayoutItem* f = form->itemAt(row, QFormLayout::FieldRole)) l->setBuddy(f->widget());
  setWidget(new ScrollingBody(this, panel));
  retranslate();

  connect(roomSurface_, &QComboBox::currentIndexChanged, this, [this] { refreshRoom(); });
  connect(roomPreset_, &QComboBox::activated, this, [this] { editRoomMaterial(); });
  connect(roomRoughness_, &QDoubleSpinBox::valueChanged, this, [this] { editRoomMaterial(); });
  connect(height_, &QDoubleSpinBox::valueChanged, this, &PropertiesDock::editHeight);
  connect(yaw_, &QDoubleSpinBox::valueChanged, this, &PropertiesDock::editYaw);
  connect(preset_, &QComboBox::activated, this, &PropertiesDock::editPreset);
  connect(albedo_, &QPushButton::clicked, this, &PropertiesDock::pickAlbedo);
  connect(name_, &QLineEdit::editingFinished, this, [this] {
    const int i = document_->selectedObject();
    if (i < 0 || name_->text() == document_->objectName(i)) return;
    QString reason;
    report(document_->renameObject(i, name_->text(), &reason), reason);
  });
  connect(shown_, &QCheckBox::clicked, this, [this](bool shown) {
    QString reason;
    report(document_->setObjectHidden(document_->selectedObject(), !shown, &reason), reason);
  });
  connect(newModelHeight_, &QDoubleSpinBox::valueChanged, this,
          [](double m) { setDefaultModelHeightM(m); });
  connect(document_, &Document::changed, this, [this] { refresh(); });
  refresh();
}

void PropertiesDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) {
    retranslate();
    refresh();
  }
  QDockWidget::changeEvent(event);
}

void PropertiesDock::retranslate() {
  setWindowTitle(tr("Properties"));
  auto* form = static_cast<QFormLayout*>(title_->parentWidget()->layout());
  auto label = [form](QWidget* field, const QString& text) {
    if (auto* l = qobject_cast<QLabel*>(form->labelForField(field))) l->setText(text);
  };
  label(name_, tr("Name:"));
  label(shown_, tr("Render:"));
  shown_->setText(tr("Shown"));
  shown_->setToolTip(tr("A hidden object stays in the scene but is not rendered"));
  label(size_, tr("Size (W × D × H):"));
  size_->setToolTip(tr("Width × depth × height in metres, as placed (before its turn)"));
  label(base_, tr("Base (px):"));
  base_->setToolTip(tr("The photo pixel the centre of the object's base stands on"));
  label(height_, tr("Height:"));
  label(yaw_, tr("Turn:"));
  label(preset_, tr("Material:"));
  label(albedo_, tr("Colour:"));
  label(roomSurface_, tr("Surface:"));
  label(roomPreset_, tr("Finish:"));
  label(roomRoughness_, tr("Roughness:"));
  height_->setSuffix(tr(" m"));
  yaw_->setSuffix(tr(" °"));
  const QString presets[] = {tr("Diffuse"), tr("Glossy"),        tr("Mirror"),   tr("Metal"),
                             tr("Glass"),   tr("Frosted glass"), tr("Emissive"), tr("From the file")};
  for (int i = 0; i < preset_->count(); ++i) preset_->setItemText(i, presets[i]);
  albedo_->setToolTip(tr("Reflectance of the object's surface"));
  roomTitle_->setText(tr("<b>Room surface</b>"));
  const QString finishes[] = {tr("Matte"), tr("Glossy"), tr("Mirror")};
  for (int i = 0; i < roomPreset_->count(); ++i) roomPreset_->setItemText(i, finishes[i]);
  roomPreset_->setToolTip(tr("A real surface of the photo that reflects: a glossy floor, a mirror"));
  newModelsTitle_->setText(tr("<b>New models</b>"));
  label(newModelHeight_, tr("Height:"));
  newModelHeight_->setSuffix(tr(" m"));
  newModelHeight_->setToolTip(
      tr("The height a model gets when its file does not state its unit "
         "(OBJ, PLY, 3DS) or states an absurd size"));
}

void PropertiesDock::refreshRoom() {
  const std::vector<std::string> names = document_->roomSurfaceNames();
  const QString current = roomSurface_->currentData().toString();
  {
    const QSignalBlocker block(roomSurface_);
    roomSurface_->clear();
    for (const std::string& n : names) {
      const QString name = QString::fromStdString(n);
      roomSurface_->addItem(roomSurfaceTitle(name), name);  // shown in the language, keyed by name
    }
    roomSurface_->setCurrentIndex(
        std::max(0, roomSurface_->findData(current.isEmpty() ? QStringLiteral("floor") : current)));
  }
  const bool editable = !names.empty();
  for (QWidget* w : {static_cast<QWidget*>(roomSurface_), static_cast<QWidget*>(roomPreset_),
                     static_cast<QWidget*>(roomRoughness_)})
    w->setEnabled(editable);
  const auto& materials = document_->scene().room.materials;
  const auto it = materials.find(roomSurface_->currentData().toString().toStdString());
  const QSignalBlocker b1(roomPreset_), b2(roomRoughness_);
  const QString preset = it == materials.end() ? QStringLiteral("diffuse")
                                               : QString::fromStdString(it->second.preset);
  roomPreset_->setCurrentIndex(std::max(0, roomPreset_->findData(preset)));
  roomRoughness_->setValue(it == materials.end() ? RoomMaterialKeys{}.roughness : it->second.roughness);
  roomRoughness_->setEnabled(editable && preset == QLatin1String("glossy"));
}

void PropertiesDock::editRoomMaterial() {
  const std::string surface = roomSurface_->currentData().toString().toStdString();
  const QString preset = roomPreset_->currentData().toString();
  std::optional<RoomMaterialKeys> material;
  if (preset != QLatin1String("diffuse")) {
    const auto& materials = document_->scene().room.materials;
    const auto it = materials.find(surface);
    material = it == materials.end() ? RoomMaterialKeys{} : it->second;
    material->preset = preset.toStdString();
    material->roughness = roomRoughness_->value();
  }
  QString reason;
  report(document_->setRoomMaterial(surface, material, &reason), reason);
}

void PropertiesDock::refresh() {
  const int i = document_->selectedObject();
  const bool valid = i >= 0 && i < document_->objectCount();
  refreshRoom();
  // Edits are taken while the scene re-prepares too (the document is the truth).
  const bool editable = valid &&
                        (document_->isReady() || document_->state() == Document::State::Preparing);
  for (QWidget* w :
       {static_cast<QWidget*>(height_), static_cast<QWidget*>(yaw_), static_cast<QWidget*>(preset_),
        static_cast<QWidget*>(albedo_), static_cast<QWidget*>(name_), static_cast<QWidget*>(shown_)})
    w->setEnabled(editable);
  const QSignalBlocker b0(name_), b4(shown_);
  if (!valid) {
    title_->setText(tr("No object selected"));
    name_->clear();
    size_->clear();
    base_->clear();
    return;
  }
  const ObjectKeys& o = document_->scene().objects[size_t(i)];
  title_->setText(tr("<b>Object %1</b> (%2)").arg(i + 1).arg(meshName(o)));
  if (!name_->hasFocus()) name_->setText(document_->objectName(i));
  shown_->setChecked(!o.hidden);
  const std::optional<Vec3> size = document_->objectSizeM(i);
  size_->setText(size ? tr("%1 × %2 × %3 m")
                            .arg(size->x(), 0, 'f', 2)
                            .arg(size->z(), 0, 'f', 2)
                            .arg(size->y(), 0, 'f', 2)
                      : tr("– (the scene is being prepared)"));
  base_->setText(QStringLiteral("%1, %2").arg(o.basePx.x(), 0, 'f', 1).arg(o.basePx.y(), 0, 'f', 1));
  const QSignalBlocker b1(height_), b2(yaw_), b3(preset_);
  height_->setValue(o.heightM);
  yaw_->setValue(o.yawDeg);
  const int presetIndex = preset_->findData(QString::fromStdString(o.material.preset));
  preset_->setCurrentIndex(std::max(0, presetIndex));
  const QColor c = displayColour(o.material.albedo);
  albedo_->setText(c.name());
  albedo_->setStyleSheet(
      QStringLiteral("QPushButton { background: %1; color: %2; }")
          .arg(c.name(), c.lightnessF() > 0.5 ? QStringLiteral("black") : QStringLiteral("white")));
}

void PropertiesDock::report(bool ok, const QString& reason) {
  if (!ok) {
    Q_EMIT statusMessage(reason);
    refresh();  // show the document's value again
  }
}

void PropertiesDock::editHeight(double heightM) {
  QString reason;
  report(document_->setObjectHeight(document_->selectedObject(), heightM, &reason), reason);
}

void PropertiesDock::editYaw(double yawDeg) {
  QString reason;
  report(document_->setObjectYaw(document_->selectedObject(), yawDeg, &reason), reason);
}

void PropertiesDock::editPreset(int comboIndex) {
  const int i = document_->selectedObject();
  if (i < 0 || i >= document_->objectCount()) return;
  MaterialKeys m = document_->scene().objects[size_t(i)].material;
  m.preset = preset_->itemData(comboIndex).toString().toStdString();
  QString reason;
  report(document_->setMaterial(i, m, &reason), reason);
}

void PropertiesDock::pickAlbedo() {
  const int i = document_->selectedObject();
  if (i < 0 || i >= document_->objectCount()) return;
  MaterialKeys m = document_->scene().objects[size_t(i)].material;
  const QColor chosen = QColorDialog::getColor(displayColour(m.albedo), this, tr("Object colour"));
  if (!chosen.isValid()) return;
  // The dialog speaks sRGB; the scene file stores linear reflectance.
  m.albedo = Vec3(srgbToLinear(float(chosen.redF())), srgbToLinear(float(chosen.greenF())),
                  srgbToLinear(float(chosen.blueF())));
  QString reason;
  report(document_->setMaterial(i, m, &reason), reason);
}

double defaultModelHeightM() {
  const double m = QSettings().value(QLatin1String(kDefaultHeightKey), kDefaultModelHeightM).toDouble();
  return m >= kMinPlausibleHeightM && m <= kMaxPlausibleHeightM ? m : kDefaultModelHeightM;
}

void setDefaultModelHeightM(double metres) {
  if (metres >= kMinPlausibleHeightM && metres <= kMaxPlausibleHeightM)
    QSettings().setValue(QLatin1String(kDefaultHeightKey), metres);
}

}  // namespace inlay::studio
