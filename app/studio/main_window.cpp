#include "main_window.h"
#include "engine_text.h"

#include "autosave.h"
#include "docks.h"
#include "final_render.h"
#include "status_bar.h"
#include "steps_dock.h"
#include "library_dock.h"
#include "log_dock.h"
#include "response_dock.h"
#include "i18n.h"
#include "image_convert.h"
#include "document.h"
#include "render_controller.h"
#include "viewport.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMimeData>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QImageReader>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QProgressDialog>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QThread>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>

namespace inlay::studio {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* const kRecentKey = "recentFiles";
const char* const kRecentModelsKey = "recentModels";

// The window icon: the SVG when Qt can read SVG here, else the same drawing painted directly
// (a box room in perspective with a sphere standing in it).
QIcon appIcon() {
  if (QImageReader::supportedImageFormats().contains("svg"))
    return QIcon(QStringLiteral(":/icons/inlay.svg"));
  QIcon icon;
  for (int size : {16, 32, 64, 128}) {
    QPixmap pm(size, size);
    pm.fill(Qt::transparent);
    QPainter p(&pm);
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(size / 64.0, size / 64.0);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(38, 50, 72));
    p.drawRoundedRect(QRectF(2, 2, 60, 60), 10, 10);
    p.setPen(QPen(QColor(90, 200, 255), 2.5));
    p.setBrush(Qt::NoBrush);
    const QRectF back(20, 16, 24, 22);
    p.drawRect(back);
    p.drawLine(back.topLeft(), QPointF(6, 6));
    p.drawLine(back.topRight(), QPointF(58, 6));
    p.drawLine(back.bottomLeft(), QPointF(6, 58));
    p.drawLine(back.bottomRight(), QPointF(58, 58));
    QRadialGradient g(QPointF(29, 38), 14);
    g.setColorAt(0, QColor(255, 210, 150));
    g.setColorAt(1, QColor(230, 120, 40));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 90));
    p.drawEllipse(QRectF(22, 49, 22, 6));
    p.setBrush(g);
    p.drawEllipse(QRectF(23, 31, 20, 20));
    p.end();
    icon.addPixmap(pm);
  }
  return icon;
}

QString stageText(const QString& stage) {
  if (stage == QLatin1String("photo")) return MainWindow::tr("Reading the photo");
  if (stage == QLatin1String("camera")) return MainWindow::tr("Estimating the camera");
  if (stage == QLatin1String("room")) return MainWindow::tr("Fitting the room");
  if (stage == QLatin1String("lighting")) return MainWindow::tr("Estimating the lighting");
  if (stage == QLatin1String("refine")) return MainWindow::tr("Refining the lights");
  if (stage == QLatin1String("objects")) return MainWindow::tr("Placing the objects");
  return stage;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setObjectName(QStringLiteral("inlayMainWindow"));
  setWindowIcon(appIcon());
  setAcceptDrops(true);
  document_ = new Document(this);
  renderer_ = new RenderController(document_, this);
  viewport_ = new Viewport(document_, renderer_, this);
  setCentralWidget(viewport_);

  sceneDock_ = new SceneTreeDock(document_, this);
  propertiesDock_ = new PropertiesDock(document_, this);
  addDockWidget(Qt::LeftDockWidgetArea, sceneDock_);
  addDockWidget(Qt::LeftDockWidgetArea, propertiesDock_);
  layersDock_ = new LayersDock(viewport_, this);
  addDockWidget(Qt::RightDockWidgetArea, layersDock_);
  addDockWidget(Qt::RightDockWidgetArea, new LibraryDock(this));  // the bundled model library
  responseDock_ = new ResponseDock(document_, this);
  addDockWidget(Qt::RightDockWidgetArea, responseDock_);
  logDock_ = new LogDock(document_, this);
  tabifyDockWidget(responseDock_, logDock_);
  responseDock_->raise();
  autosaver_ = new Autosaver(document_, this);

  sppLabel_ = new QLabel(this);
  rateLabel_ = new QLabel(this);
  errorLabel_ = new QLabel(this);
  timeLabel_ = new QLabel(this);
  zoomLabel_ = new QLabel(this);
  // Transient messages wrap in the bar (status_bar.h); in a narrow window the rate goes first,
  // then the zoom, then the time.
  statusBar_ = new StatusBar(this);
  setStatusBar(statusBar_);
  statusBar_->addField(sppLabel_, 0);
  statusBar_->addField(rateLabel_, 1);
  statusBar_->addField(errorLabel_, 0);
  statusBar_->addField(timeLabel_, 3);
  statusBar_->addField(zoomLabel_, 2);
  auto showZoom = [this](double zoom) { zoomLabel_->setText(tr("%1 %").arg(qRound(zoom * 100))); };
  connect(viewport_, &Viewport::zoomChanged, this, showZoom);
  showZoom(viewport_->zoom());

  createActions();
  createStepsDock();
  createMenus();
  retranslate();

  connect(document_, &Document::changed, this, &MainWindow::onDocumentChanged);
  connect(document_->undoStack(), &QUndoStack::cleanChanged, this, [this] { updateTitle(); });
  connect(document_, &Document::prepareProgress, this, [this](const QString& stage, double f) {
    prepareStage_ = stage;
    prepareFraction_ = f;
    showPrepareProgress();
  });
  // The seconds tick on while a stage reports no fraction: the dialog never looks frozen.
  prepareTicker_ = new QTimer(this);
  prepareTicker_->setInterval(1000);
  connect(prepareTicker_, &QTimer::timeout, this, &MainWindow::showPrepareProgress);
  connect(renderer_, &RenderController::frameUpdated, this, &MainWindow::onFrame);
  connect(viewport_, &Viewport::statusMessage, this, [this](const QString& m) {
    if (m.isEmpty()) statusBar()->clearMessage();
    else statusBar()->showMessage(m, 5000);
  });
  connect(viewport_, &Viewport::modelDropped, this, [this](const QString& path, QPointF imagePx) {
    insertModelFile(path, Vec2(imagePx.x(), imagePx.y()));
  });
  connect(propertiesDock_, &PropertiesDock::statusMessage, this,
          [this](const QString& m) { statusBar()->showMessage(m, 5000); });

  const QSettings settings;
  if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray()))
    resize(1200, 800);
  restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
  // Done once: the steps stay out of the way (View > Steps shows them again).
  if (settings.value(QStringLiteral("guide/done")).toBool()) stepsDock_->hide();
  updateTitle();
  onFrame();
  onDocumentChanged({});  // the actions' enabled states for an empty document
}

MainWindow::~MainWindow() {
  // A final render still running (a non-interactive close): stopped and joined without
  // reporting to this half-destroyed window.
  if (finalRender_) {
    QObject::disconnect(finalRender_, nullptr, this, nullptr);
    delete finalRender_;
  }
  // A model still being read: its thread ends by itself (it touches no window); wait for it.
  for (QThread* t : std::as_const(loaders_)) {
    QObject::disconnect(t, nullptr, this, nullptr);
    t->wait();
    delete t;
  }
  loaders_.clear();
  // Stop the render thread before the document it renders goes away.
  delete renderer_;
  renderer_ = nullptr;
  // The document is deleted with the children, after this destructor: its undo stack's clear()
  // then emits indexChanged, and a slot of this half-destroyed window would run (UBSan: member
  // call on an object that is only a QWidget any more). Nothing of the document reaches us now.
  QObject::disconnect(document_->undoStack(), nullptr, this, nullptr);
  QObject::disconnect(document_, nullptr, this, nullptr);
}

void MainWindow::createActions() {
  QStyle* s = style();
  openSceneAct_ = new QAction(s->standardIcon(QStyle::SP_DialogOpenButton), QString(), this);
  openSceneAct_->setShortcut(QKeySequence::Open);
  connect(openSceneAct_, &QAction::triggered, this, &MainWindow::openSceneDialog);

  openPhotoAct_ = new QAction(this);
  openPhotoAct_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
  connect(openPhotoAct_, &QAction::triggered, this, &MainWindow::openPhotoDialog);

  openExampleAct_ = new QAction(this);
  connect(openExampleAct_, &QAction::triggered, this, [this] { openExample(); });

  saveAct_ = new QAction(s->standardIcon(QStyle::SP_DialogSaveButton), QString(), this);
  saveAct_->setShortcut(QKeySequence::Save);
  connect(saveAct_, &QAction::triggered, this, &MainWindow::save);

  saveAsAct_ = new QAction(this);
  saveAsAct_->setShortcut(QKeySequence::SaveAs);
  connect(saveAsAct_, &QAction::triggered, this, &MainWindow::saveAsDialog);

  exportAct_ = new QAction(this);
  exportAct_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
  connect(exportAct_, &QAction::triggered, this, &MainWindow::exportCompositeDialog);

  exportLayerAct_ = new QAction(this);
  connect(exportLayerAct_, &QAction::triggered, this, &MainWindow::exportLayerDialog);
  exportGltfAct_ = new QAction(this);
  connect(exportGltfAct_, &QAction::triggered, this, &MainWindow::exportSceneGltfDialog);
  renderFinalAct_ = new QAction(s->standardIcon(QStyle::SP_MediaPlay), QString(), this);
  renderFinalAct_->setObjectName(QStringLiteral("renderFinalAction"));
  renderFinalAct_->setShortcut(QKeySequence(Qt::Key_F12));
  connect(renderFinalAct_, &QAction::triggered, this, &MainWindow::renderFinalDialog);

  quitAct_ = new QAction(this);
  quitAct_->setShortcut(QKeySequence::Quit);
  connect(quitAct_, &QAction::triggered, this, &QWidget::close);

  // Our own undo / redo actions rather than QUndoStack's: those keep the prefix they were made
  // with, and a language switch must change it.
  QUndoStack* stack = document_->undoStack();
  undoAct_ = new QAction(s->standardIcon(QStyle::SP_ArrowBack), QString(), this);
  undoAct_->setShortcut(QKeySequence::Undo);
  connect(undoAct_, &QAction::triggered, stack, &QUndoStack::undo);
  redoAct_ = new QAction(s->standardIcon(QStyle::SP_ArrowForward), QString(), this);
  redoAct_->setShortcut(QKeySequence::Redo);
  connect(redoAct_, &QAction::triggered, stack, &QUndoStack::redo);
  connect(stack, &QUndoStack::indexChanged, this, [this] { updateUndoActions(); });
  connect(stack, &QUndoStack::cleanChanged, this, [this] { updateUndoActions(); });

  insertSphereAct_ = new QAction(this);
  connect(insertSphereAct_, &QAction::triggered, this,
          [this] { insertBuiltin(QStringLiteral("builtin:sphere")); });
  insertCubeAct_ = new QAction(this);
  connect(insertCubeAct_, &QAction::triggered, this,
          [this] { insertBuiltin(QStringLiteral("builtin:cube")); });
  deleteAct_ = new QAction(this);
  deleteAct_->setShortcut(QKeySequence::Delete);
  connect(deleteAct_, &QAction::triggered, this, &MainWindow::deleteSelected);
  insertModelAct_ = new QAction(s->standardIcon(QStyle::SP_FileDialogNewFolder), QString(), this);
  insertModelAct_->setObjectName(QStringLiteral("insertModelAction"));
  insertModelAct_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I));
  connect(insertModelAct_, &QAction::triggered, this, &MainWindow::insertModelDialog);
  duplicateAct_ = new QAction(this);
  duplicateAct_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
  connect(duplicateAct_, &QAction::triggered, this, &MainWindow::duplicateSelected);
  hideAct_ = new QAction(this);
  hideAct_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_H));
  connect(hideAct_, &QAction::triggered, this, &MainWindow::toggleSelectedHidden);
  renameAct_ = new QAction(this);
  renameAct_->setShortcut(QKeySequence(Qt::Key_F2));
  connect(renameAct_, &QAction::triggered, this, &MainWindow::renameSelected);

  zoomInAct_ = new QAction(this);
  zoomInAct_->setShortcut(QKeySequence::ZoomIn);
  connect(zoomInAct_, &QAction::triggered, viewport_, &Viewport::zoomIn);
  zoomOutAct_ = new QAction(this);
  zoomOutAct_->setShortcut(QKeySequence::ZoomOut);
  connect(zoomOutAct_, &QAction::triggered, viewport_, &Viewport::zoomOut);
  fitAct_ = new QAction(this);
  fitAct_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
  connect(fitAct_, &QAction::triggered, viewport_, &Viewport::zoomToFit);
  beforeAct_ = new QAction(this);
  beforeAct_->setCheckable(true);
  beforeAct_->setShortcut(QKeySequence(Qt::Key_B));
  connect(beforeAct_, &QAction::toggled, viewport_, &Viewport::setShowBefore);
  denoiseAct_ = new QAction(this);
  denoiseAct_->setCheckable(true);
  denoiseAct_->setChecked(QSettings().value(QStringLiteral("denoisePreview"), true).toBool());
  renderer_->setDenoise(denoiseAct_->isChecked());
  connect(denoiseAct_, &QAction::toggled, this, [this](bool on) {
    QSettings().setValue(QStringLiteral("denoisePreview"), on);
    renderer_->setDenoise(on);
  });
  splitAct_ = new QAction(this);
  splitAct_->setCheckable(true);
  splitAct_->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_B));
  connect(splitAct_, &QAction::toggled, viewport_, &Viewport::setSplitView);

  acceptBoxAct_ = new QAction(this);
  connect(acceptBoxAct_, &QAction::triggered, this, [this] {
    QString reason;
    if (!document_->acceptEstimatedBox(&reason)) statusBar()->showMessage(reason, 5000);
  });
  resetBoxAct_ = new QAction(this);
  connect(resetBoxAct_, &QAction::triggered, this, [this] {
    QString reason;
    if (!document_->resetBackWall(&reason)) statusBar()->showMessage(reason, 5000);
  });
  prepareAct_ = new QAction(this);
  prepareAct_->setShortcut(QKeySequence::Refresh);
  connect(prepareAct_, &QAction::triggered, document_, &Document::prepare);
  vanishingAct_ = new QAction(this);
  vanishingAct_->setCheckable(true);
  vanishingAct_->setChecked(viewport_->showsVanishingLines());
  connect(vanishingAct_, &QAction::toggled, viewport_, &Viewport::setShowVanishingLines);

  auto* tools = new QActionGroup(this);
  const QKeySequence toolKeys[] = {QKeySequence(Qt::Key_V), QKeySequence(Qt::Key_L),
                                   QKeySequence(Qt::Key_H), QKeySequence(Qt::Key_T),
                                   QKeySequence(Qt::Key_O), QKeySequence(Qt::Key_P)};
  for (int i = 0; i < 6; ++i) {
    QAction* a = tools->addAction(QString());
    a->setCheckable(true);
    a->setShortcut(toolKeys[i]);
    a->setChecked(i == 0);
    connect(a, &QAction::triggered, this, [this, i] { viewport_->setTool(Viewport::Tool(i)); });
    toolActs_ << a;
  }

  aboutAct_ = new QAction(this);
  connect(aboutAct_, &QAction::triggered, this, &MainWindow::about);
}

void MainWindow::createMenus() {
  fileMenu_ = menuBar()->addMenu(QString());
  fileMenu_->addAction(openSceneAct_);
  fileMenu_->addAction(openPhotoAct_);
  fileMenu_->addAction(openExampleAct_);
  recentMenu_ = fileMenu_->addMenu(QString());
  connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::rebuildRecentMenu);
  rebuildRecentMenu();
  fileMenu_->addSeparator();
  fileMenu_->addAction(saveAct_);
  fileMenu_->addAction(saveAsAct_);
  fileMenu_->addAction(renderFinalAct_);
  fileMenu_->addAction(exportAct_);
  fileMenu_->addAction(exportLayerAct_);
  fileMenu_->addAction(exportGltfAct_);
  fileMenu_->addSeparator();
  fileMenu_->addAction(quitAct_);

  editMenu_ = menuBar()->addMenu(QString());
  QMenu* edit = editMenu_;
  edit->addAction(undoAct_);
  edit->addAction(redoAct_);
  edit->addSeparator();
  edit->addAction(insertModelAct_);
  edit->addAction(insertSphereAct_);
  edit->addAction(insertCubeAct_);
  edit->addSeparator();
  edit->addAction(duplicateAct_);
  edit->addAction(renameAct_);
  edit->addAction(hideAct_);
  edit->addAction(deleteAct_);
  edit->addSeparator();
  edit->addAction(acceptBoxAct_);
  edit->addAction(resetBoxAct_);
  edit->addAction(prepareAct_);

  toolsMenu_ = menuBar()->addMenu(QString());
  toolsMenu_->addActions(toolActs_);

  viewMenu_ = menuBar()->addMenu(QString());
  QMenu* view = viewMenu_;
  view->addAction(zoomInAct_);
  view->addAction(zoomOutAct_);
  view->addAction(fitAct_);
  view->addSeparator();
  view->addAction(beforeAct_);
  view->addAction(splitAct_);
  view->addAction(vanishingAct_);
  view->addAction(denoiseAct_);
  view->addSeparator();
  view->addAction(stepsDock_->toggleViewAction());
  view->addAction(sceneDock_->toggleViewAction());
  view->addAction(propertiesDock_->toggleViewAction());
  view->addAction(layersDock_->toggleViewAction());
  view->addAction(responseDock_->toggleViewAction());
  view->addAction(logDock_->toggleViewAction());
  view->addSeparator();
  languageMenu_ = view->addMenu(QString());
  QMenu* language = languageMenu_;
  auto* group = new QActionGroup(language);
  const QString current = QSettings().value(QStringLiteral("language")).toString();
  const std::pair<QString, QString> languages[] = {{QString(), QString()},
                                                   {QStringLiteral("en"), QStringLiteral("English")},
                                                   {QStringLiteral("de"), QStringLiteral("Deutsch")},
                                                   {QStringLiteral("fr"), QStringLiteral("Français")}};
  for (const auto& [code, name] : languages) {
    QAction* a = language->addAction(name);
    if (code.isEmpty()) systemLanguageAct_ = a;
    a->setCheckable(true);
    a->setChecked(code == current);
    group->addAction(a);
    connect(a, &QAction::triggered, this, [this, code = code] { setLanguage(code); });
  }

  helpMenu_ = menuBar()->addMenu(QString());
  QMenu* help = helpMenu_;
  help->addAction(aboutAct_);

  mainToolBar_ = addToolBar(QString());
  QToolBar* tools = mainToolBar_;
  tools->setObjectName(QStringLiteral("mainToolBar"));
  tools->addAction(openSceneAct_);
  tools->addAction(saveAct_);
  tools->addSeparator();
  tools->addAction(undoAct_);
  tools->addAction(redoAct_);
  tools->addSeparator();
  tools->addActions(toolActs_);
  tools->addSeparator();
  tools->addAction(insertModelAct_);
  tools->addAction(renderFinalAct_);
  tools->addSeparator();
  tools->addAction(zoomInAct_);
  tools->addAction(zoomOutAct_);
  tools->addAction(fitAct_);
  tools->addAction(beforeAct_);
}

void MainWindow::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QMainWindow::changeEvent(event);
}

// Every text of the window's own menus, actions, toolbar and status bar, in the current
// language (called at creation and on each QEvent::LanguageChange; the docks and the viewport
// retranslate themselves).
void MainWindow::retranslate() {
  openSceneAct_->setText(tr("&Open Scene…"));
  openPhotoAct_->setText(tr("Open &Photo…"));
  openExampleAct_->setText(tr("Open &Example"));
  saveAct_->setText(tr("&Save"));
  saveAsAct_->setText(tr("Save &As…"));
  exportAct_->setText(tr("&Export Composite…"));
  exportLayerAct_->setText(tr("Export Shown &Layer…"));
  exportGltfAct_->setText(tr("Export Scene as &glTF…"));
  renderFinalAct_->setText(tr("&Render Final Image…"));
  renderFinalAct_->setStatusTip(
      tr("Render the composite at the photo's full resolution until it is clean, "
         "then save it (PNG, JPEG, TIFF or EXR)"));
  splitAct_->setText(tr("Before/After &Split"));
  splitAct_->setStatusTip(
      tr("The photo left of a divider, the composite right of it; drag the divider"));
  quitAct_->setText(tr("&Quit"));
  insertSphereAct_->setText(tr("Insert &Sphere"));
  insertCubeAct_->setText(tr("Insert &Cube"));
  deleteAct_->setText(tr("&Delete"));
  insertModelAct_->setText(tr("Insert &Model…"));
  insertModelAct_->setStatusTip(
      tr("Stand a 3D model (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) on the floor; "
         "or drop the file where it should stand"));
  duplicateAct_->setText(tr("D&uplicate"));
  duplicateAct_->setStatusTip(tr("Stand a copy of the selected object beside it"));
  renameAct_->setText(tr("Re&name…"));
  renameAct_->setStatusTip(tr("Rename the selected object (in the Scene list)"));
  hideAct_->setText(tr("&Hide or Show"));
  hideAct_->setStatusTip(tr("Hide the selected object from the render, or show it again"));
  zoomInAct_->setText(tr("Zoom &In"));
  zoomOutAct_->setText(tr("Zoom &Out"));
  fitAct_->setText(tr("&Fit to Window"));
  beforeAct_->setText(tr("&Before (Photo Only)"));
  acceptBoxAct_->setText(tr("&Accept Estimated Box"));
  resetBoxAct_->setText(tr("Estimate the &Box Again"));
  prepareAct_->setText(tr("&Prepare the Scene Again"));
  vanishingAct_->setText(tr("&Vanishing Lines and Confidence"));
  denoiseAct_->setText(tr("&Denoise Preview"));
  denoiseAct_->setStatusTip(
      tr("Smooth the render's noise where the objects change the photo (the rest stays the photo)"));
  aboutAct_->setText(tr("&About Inlay"));
  openSceneAct_->setStatusTip(tr("Open a scene file (.json)"));
  openPhotoAct_->setStatusTip(tr("Start a new scene from a photo"));
  exportAct_->setStatusTip(tr("Write the current composite as PNG, JPEG, TIFF or EXR"));
  exportLayerAct_->setStatusTip(
      tr("Write the layer the viewport shows (albedo, mask, …) as an 8-bit image"));
  exportGltfAct_->setStatusTip(
      tr("Write the room, its lights, the camera and the objects as glTF 2.0, to go on in Blender"));
  insertSphereAct_->setStatusTip(tr("Stand a sphere on the floor in the middle of the photo"));
  insertCubeAct_->setStatusTip(tr("Stand a cube on the floor in the middle of the photo"));
  deleteAct_->setStatusTip(tr("Delete the selected object or mark"));
  beforeAct_->setStatusTip(tr("Toggle between the photo and the composite with the objects"));
  acceptBoxAct_->setStatusTip(tr("Keep the estimated back wall as yours"));
  resetBoxAct_->setStatusTip(tr("Forget your corners of the back wall"));
  prepareAct_->setStatusTip(tr("Estimate the camera, room and lighting again (after a cancel)"));
  sppLabel_->setToolTip(tr("Samples per pixel of the shown composite"));
  rateLabel_->setToolTip(tr("Samples per second of the renderer (millions)"));
  errorLabel_->setToolTip(tr("Estimated error (RMSE in sRGB) where the objects change the photo"));
  timeLabel_->setToolTip(tr("Render time since the last change"));
  zoomLabel_->setToolTip(tr("Zoom"));
  const QString toolNames[] = {tr("&Select and Move"),  tr("Outline a &Light"),
                               tr("Sun &Shaft"),        tr("&Table Top or Step"),
                               tr("&Occluder Strokes"), tr("&Vanishing Lines (X, Y, Z)")};
  for (int i = 0; i < toolActs_.size(); ++i) toolActs_[i]->setText(toolNames[i]);
  fileMenu_->setTitle(tr("&File"));
  recentMenu_->setTitle(tr("Open &Recent"));
  editMenu_->setTitle(tr("&Edit"));
  toolsMenu_->setTitle(tr("&Tools"));
  viewMenu_->setTitle(tr("&View"));
  languageMenu_->setTitle(tr("&Language"));
  systemLanguageAct_->setText(tr("System Default"));
  helpMenu_->setTitle(tr("&Help"));
  mainToolBar_->setWindowTitle(tr("Main"));
  document_->retranslateHistory();  // the commands' texts first: the actions are built from them
  updateUndoActions();
  updateTitle();
  fitStatusFields();
  showFinalTexts();
  onFrame();
}

// The status bar's fields as wide as the widest text each shows in this language, so the
// message beside them does not re-wrap at every frame.
void MainWindow::fitStatusFields() {
  statusBar_->setFieldSamples(sppLabel_, {tr("preview 1/%1").arg(16), tr("%1 spp, done").arg(1024),
                                          tr("final, %1 spp").arg(256), tr("– spp")});
  statusBar_->setFieldSamples(rateLabel_,
                              {tr("%1 M samples/s").arg(10.0, 0, 'f', 2), tr("– samples/s")});
  statusBar_->setFieldSamples(errorLabel_, {tr("error %1").arg(0.0, 0, 'f', 4), tr("error –")});
  statusBar_->setFieldSamples(timeLabel_, {tr("%1 s").arg(100.0, 0, 'f', 1), tr("– s")});
  statusBar_->setFieldSamples(zoomLabel_, {tr("%1 %").arg(800)});
}

void MainWindow::updateUndoActions() {
  const QUndoStack* stack = document_->undoStack();
  undoAct_->setEnabled(stack->canUndo());
  redoAct_->setEnabled(stack->canRedo());
  undoAct_->setText(stack->canUndo() ? tr("&Undo %1").arg(stack->undoText()) : tr("&Undo"));
  redoAct_->setText(stack->canRedo() ? tr("&Redo %1").arg(stack->redoText()) : tr("&Redo"));
}

void MainWindow::onDocumentChanged(const ChangeEvent& event) {
  // An edit (anything but a selection or a file name) ends the final image's showing.
  if (event.what & ~unsigned(ChangeEvent::Selection | ChangeEvent::FilePath)) dropFinalImage();
  if (event.has(ChangeEvent::FilePath) || event.has(ChangeEvent::SceneReplaced)) updateTitle();
  if (event.has(ChangeEvent::PrepareStarted)) {
    delete progress_;
    progress_ = new QProgressDialog(tr("Preparing the scene…"), tr("Cancel"), 0, 1000, this);
    progress_->setWindowTitle(tr("Inlay"));
    // Not modal: a modal QProgressDialog::setValue() runs processEvents(), and the progress
    // slot would re-enter. Edits are refused by the document while it prepares anyway.
    progress_->setWindowModality(Qt::NonModal);
    // At once: a message that comes later (a refused model) must open above it, not below.
    progress_->setMinimumDuration(interactive_ ? 0 : 1000000000);
    progress_->setAutoClose(false);
    progress_->setAutoReset(false);
    connect(progress_, &QProgressDialog::canceled, document_, &Document::cancelPrepare);
    prepareStage_.clear();
    prepareFraction_ = 0;
    prepareClock_.start();
    prepareTicker_->start();
    showPrepareProgress();
    statusBar()->showMessage(tr("Preparing the scene…"));
    statusBar()->setToolTip(QString());
  }
  if (event.has(ChangeEvent::SceneReplaced)) {
    reportFailure_ = true;
    waitingModels_.clear();  // they were meant for the scene that was closed
  }
  if (event.has(ChangeEvent::Marks)) reportFailure_ = false;
  if (event.has(ChangeEvent::PrepareFinished)) {
    prepareTicker_->stop();
    if (progress_) {
      progress_->hide();
      progress_->deleteLater();
      progress_ = nullptr;
    }
    statusBar()->clearMessage();
    switch (document_->state()) {
      case Document::State::Failed:
        // After an open: a dialog. After an edit of the marks: the viewport's banner says it.
        if (reportFailure_)
          showError(tr("The scene could not be prepared"), engineText(document_->prepareError()));
        else statusBar()->showMessage(engineText(document_->prepareError()), 10000);
        break;
      case Document::State::Ready:
        if (!document_->warnings().isEmpty()) {
          // The first note in the bar, all of them in its tooltip.
          const QStringList w = engineTexts(document_->warnings());
          statusBar()->showMessage(
              w.size() == 1 ? w.first()
                            : tr("%1 (and %n more)", nullptr, int(w.size() - 1)).arg(w.first()),
              10000);
          statusBar()->setToolTip(w.join(QLatin1Char('\n')));
        }
        break;
      default: statusBar()->showMessage(engineText(document_->prepareError()), 5000); break;
    }
  }
  const bool ready = document_->isReady();
  exportAct_->setEnabled(ready);
  exportGltfAct_->setEnabled(ready);
  renderFinalAct_->setEnabled(ready && !finalRender_);
  insertSphereAct_->setEnabled(ready);
  insertCubeAct_->setEnabled(ready);
  // Models may be chosen while the scene prepares: they go in once it is ready.
  insertModelAct_->setEnabled(!document_->scene().photo.empty());
  const int selected = document_->selectedObject();
  duplicateAct_->setEnabled(ready && selected >= 0);
  const bool objectEditable = selected >= 0 &&
                              (ready || document_->state() == Document::State::Preparing);
  renameAct_->setEnabled(objectEditable);
  hideAct_->setEnabled(objectEditable);
  if (event.has(ChangeEvent::PrepareFinished) && !waitingModels_.empty()) {
    std::vector<WaitingModel> waiting;
    waiting.swap(waitingModels_);
    if (ready) {
      for (const WaitingModel& m : waiting) placeModel(m.model, m.dropPx);
    } else {
      for (const WaitingModel& m : waiting)
        refuseModel(tr("%1: the scene could not be prepared, so the model has nowhere to stand.")
                        .arg(QFileInfo(m.model.path).fileName()));
    }
  }
  deleteAct_->setEnabled(!document_->scene().photo.empty());
  acceptBoxAct_->setEnabled(document_->shownBackWallPx().has_value() && !document_->backWallIsUsers());
  resetBoxAct_->setEnabled(document_->backWallIsUsers());
  prepareAct_->setEnabled(!document_->scene().photo.empty() &&
                          document_->state() != Document::State::Preparing);
  saveAct_->setEnabled(document_->state() != Document::State::Empty ||
                       !document_->scene().photo.empty());
  saveAsAct_->setEnabled(saveAct_->isEnabled());
}

// The preparation's dialog: the stage, the seconds since it began, and the stage's fraction
// (a busy bar while the stage has reported none: the lighting, for one, reports only its end).
void MainWindow::showPrepareProgress() {
  if (!progress_) return;
  const QString stage = prepareStage_.isEmpty()
                            ? tr("Preparing the scene…")
                            : tr("Preparing the scene: %1…").arg(stageText(prepareStage_));
  progress_->setLabelText(stage + QStringLiteral("  %1 s").arg(prepareClock_.elapsed() / 1000));
  if (prepareFraction_ > 0) {
    if (progress_->maximum() == 0) progress_->setRange(0, 1000);
    progress_->setValue(int(std::clamp(prepareFraction_, 0.0, 1.0) * 999));
  } else if (progress_->maximum() != 0) {
    progress_->setRange(0, 0);
  }
}

void MainWindow::onFrame() {
  if (viewport_->showsFinalImage()) {  // the final render's figures, not the preview's
    sppLabel_->setText(tr("final, %1 spp").arg(finalFigures_.spp));
    rateLabel_->setText(tr("– samples/s"));
    errorLabel_->setText(tr("error %1").arg(finalFigures_.estimatedError, 0, 'f', 4));
    timeLabel_->setText(tr("%1 s").arg(finalFigures_.seconds, 0, 'f', 1));
    exportAct_->setEnabled(true);
    return;
  }
  if (!renderer_->hasFrame()) {
    sppLabel_->setText(tr("– spp"));
    rateLabel_->setText(tr("– samples/s"));
    errorLabel_->setText(tr("error –"));
    timeLabel_->setText(tr("– s"));
    return;
  }
  const CompositeImage& f = renderer_->frameInfo();
  sppLabel_->setText(f.resolutionDivider > 1 ? tr("preview 1/%1").arg(f.resolutionDivider)
                     : f.final               ? tr("%1 spp, done").arg(f.spp)
                                             : tr("%1 spp").arg(f.spp));
  errorLabel_->setText(tr("error %1").arg(f.estimatedError, 0, 'f', 4));
  const double pixels = double(renderer_->compositeImage().width()) *
                        renderer_->compositeImage().height();
  rateLabel_->setText(f.seconds > 0
                          ? tr("%1 M samples/s").arg(f.spp * pixels / f.seconds * 1e-6, 0, 'f', 2)
                          : tr("– samples/s"));
  timeLabel_->setText(tr("%1 s").arg(f.seconds, 0, 'f', 1));
  exportAct_->setEnabled(true);
}

void MainWindow::updateTitle() {
  const QString path = document_->filePath();
  QString name;
  if (!path.isEmpty()) name = QFileInfo(path).fileName();
  else if (!document_->scene().photo.empty())
    name =
        tr("%1 (new scene)").arg(QFileInfo(QString::fromStdString(document_->scene().photo)).fileName());
  else name = tr("Untitled");
  setWindowTitle(tr("%1[*] — Inlay").arg(name));
  setWindowModified(!document_->undoStack()->isClean());
}

void MainWindow::showError(const QString& title, const QString& text) {
  statusBar()->showMessage(text, 10000);
  if (!interactive_) {
    qWarning("inlay: %s: %s", qUtf8Printable(title), qUtf8Printable(text));
    return;
  }
  // Window-modal and asynchronous: never blocks a caller (or a test) in a nested event loop.
  auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  // A progress dialog not shown yet would open later on top of the message: shown first.
  for (QProgressDialog* d : {progress_.data(), finalProgress_.data()})
    if (d && !d->isVisible()) d->show();
  box->open();
  box->raise();
}

bool MainWindow::openPath(const QString& path) {
  if (!settleFinalRender(tr("Cancel the Render and Open"), [this, path] { openPath(path); }))
    return false;
  const QFileInfo info(path);
  if (!info.exists()) {
    showError(tr("Cannot open"), tr("%1: no such file").arg(path));
    return false;
  }
  if (info.suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) == 0) {
    QString error;
    if (!document_->openSceneFile(info.absoluteFilePath(), &error)) {
      showError(tr("Cannot open the scene"), engineText(error));
      return false;
    }
  } else {
    document_->newFromPhoto(info.absoluteFilePath());
  }
  addRecentFile(info.absoluteFilePath());
  return true;
}

bool MainWindow::openExample() {
  const std::string onDisk = exampleScenePath();
  if (!onDisk.empty()) return openPath(QString::fromStdString(onDisk));
  return openEmbeddedExample();
}

bool MainWindow::openEmbeddedExample() {
  // Unpacked whole: scene.json refers to its photo (and any mesh) by relative paths.
  if (!QFile::exists(QStringLiteral(":/example/scene.json"))) {
    showError(tr("Cannot open the example"), tr("The example scene is not installed."));
    return false;
  }
  exampleCopy_ = std::make_unique<QTemporaryDir>();
  QDirIterator it(QStringLiteral(":/example"), QDir::Files, QDirIterator::Subdirectories);
  while (it.hasNext()) {
    const QString from = it.next();
    const QString to = exampleCopy_->filePath(from.mid(QStringLiteral(":/example/").size()));
    QDir().mkpath(QFileInfo(to).absolutePath());
    if (!QFile::copy(from, to)) {
      showError(tr("Cannot open the example"), tr("Cannot write %1").arg(to));
      return false;
    }
    QFile::setPermissions(to, QFile::ReadOwner | QFile::WriteOwner);
  }
  return openPath(exampleCopy_->filePath(QStringLiteral("scene.json")));
}

void MainWindow::openSceneDialog() {
  if (!maybeSave()) return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), QString(),
                                                    tr("Inlay scenes (*.json);;All files (*)"));
  if (!path.isEmpty()) openPath(path);
}

void MainWindow::openPhotoDialog() {
  if (!maybeSave()) return;
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open Photo"), QString(),
      tr("Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)"));
  if (!path.isEmpty()) openPath(path);
}

bool MainWindow::saveTo(const QString& path) {
  QString error;
  if (!document_->saveAs(path, &error)) {
    showError(tr("Cannot save the scene"), error);
    return false;
  }
  addRecentFile(document_->filePath());
  statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 4000);
  return true;
}

bool MainWindow::save() {
  if (document_->filePath().isEmpty()) return saveAsDialog();
  return saveTo(document_->filePath());
}

bool MainWindow::saveAsDialog() {
  QString suggestion = document_->filePath();
  if (suggestion.isEmpty() && !document_->scene().photoResolved.empty()) {
    const QFileInfo photo(QString::fromStdString(document_->scene().photoResolved));
    suggestion = photo.absoluteDir().filePath(photo.completeBaseName() + QStringLiteral(".json"));
  }
  QString path =
      QFileDialog::getSaveFileName(this, tr("Save Scene As"), suggestion, tr("Inlay scenes (*.json)"));
  if (path.isEmpty()) return false;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
  return saveTo(path);
}

void MainWindow::exportCompositeDialog() {
  if (!renderer_->compositeLinear()) {
    showError(tr("Nothing to export"), tr("The composite has not been rendered yet."));
    return;
  }
  const QString path = askImagePath(tr("Export Composite"), QString());
  if (!path.isEmpty()) exportComposite(path);
}

// A save dialog for a composite image (PNG, JPEG, TIFF or linear EXR); a name without a suffix
// gets the chosen type's. Empty when the user cancels.
QString MainWindow::askImagePath(const QString& title, const QString& suggestion) {
  QString selected;
  const QStringList filters = compositeImageFilters();
  const QString &jpeg = filters[1], &tiff = filters[2], &exr = filters[3];
  QString path = QFileDialog::getSaveFileName(this, title, suggestion,
                                              filters.join(QStringLiteral(";;")), &selected);
  if (path.isEmpty() || !QFileInfo(path).suffix().isEmpty()) return path;
  return path + (selected == jpeg   ? QStringLiteral(".jpg")
                 : selected == tiff ? QStringLiteral(".tif")
                 : selected == exr  ? QStringLiteral(".exr")
                                    : QStringLiteral(".png"));
}

QStringList MainWindow::compositeImageFilters() {
  return {tr("PNG image (*.png)"), tr("JPEG image (*.jpg *.jpeg)"), tr("TIFF image (*.tif *.tiff)"),
          tr("OpenEXR, linear (*.exr)")};
}

bool MainWindow::exportComposite(const QString& path) {
  const std::shared_ptr<const ImageF> linear = finalLinear_ ? finalLinear_
                                                            : renderer_->compositeLinear();
  if (!linear) {
    showError(tr("Nothing to export"), tr("The composite has not been rendered yet."));
    return false;
  }
  SaveOptions save;  // 8-bit files through the photo's camera response (its codes kept)
  const PreparedScene* prepared = document_->prepared();
  if (prepared && prepared->photo.wasSrgbEncoded) save.response = &prepared->response;
  const Status saved = saveImage(QDir::toNativeSeparators(path).toStdString(), *linear, save);
  if (!saved.ok()) {
    showError(tr("Cannot export the composite"), QString::fromStdString(saved.error().message()));
    return false;
  }
  const QSize preview = renderer_->previewSize();
  if (finalLinear_)
    statusBar()->showMessage(tr("Exported %1 (the final render)").arg(QDir::toNativeSeparators(path)),
                             5000);
  else if (prepared && preview.width() < prepared->camera.widthPx)
    // A big photo's preview is smaller than the photo: say so, and where the full size is.
    statusBar()->showMessage(
        tr("Exported %1 (%2 spp, the preview's %3 × %4; Render Final Image writes the photo's full size)")
            .arg(QDir::toNativeSeparators(path))
            .arg(renderer_->frameInfo().spp)
            .arg(preview.width())
            .arg(preview.height()),
        10000);
  else
    statusBar()->showMessage(
        tr("Exported %1 (%2 spp)").arg(QDir::toNativeSeparators(path)).arg(renderer_->frameInfo().spp),
        5000);
  stepsDock_->markExported(path);
  return true;
}

void MainWindow::createStepsDock() {
  StepsDock::Actions actions;
  actions.openPhoto = openPhotoAct_;
  actions.acceptBox = acceptBoxAct_;
  actions.outlineLight = toolActs_.value(int(Viewport::Tool::Light));
  actions.insertModel = insertModelAct_;
  actions.renderFinal = renderFinalAct_;
  stepsDock_ = new StepsDock(document_, actions, this);
  addDockWidget(Qt::LeftDockWidgetArea, stepsDock_);
  // The steps on top: Steps, Scene, Properties.
  splitDockWidget(stepsDock_, sceneDock_, Qt::Vertical);
  splitDockWidget(sceneDock_, propertiesDock_, Qt::Vertical);
  connect(stepsDock_, &StepsDock::allDone, this, [this] {
    QSettings settings;
    if (settings.value(QStringLiteral("guide/done")).toBool()) return;  // brought back by the user
    settings.setValue(QStringLiteral("guide/done"), true);
    stepsDock_->hide();
    statusBar()->showMessage(tr("All four steps done. View > Steps shows them again."), 8000);
  });
}

void MainWindow::renderFinalDialog() {
  if (!document_->isReady()) {
    showError(tr("Nothing to render"), tr("The scene is not prepared yet."));
    return;
  }
  QString suggestion;
  if (!document_->scene().photoResolved.empty()) {
    const QFileInfo photo(QString::fromStdString(document_->scene().photoResolved));
    suggestion = photo.absoluteDir().filePath(photo.completeBaseName() + QStringLiteral("_inlay.png"));
  }
  const QString path = askImagePath(tr("Render Final Image"), suggestion);
  if (!path.isEmpty()) renderFinalImage(path);
}

bool MainWindow::renderFinalImage(const QString& path, int maxSpp) {
  const PreparedScene* prepared = document_->prepared();
  if (!document_->isReady() || !prepared) {
    showError(tr("Nothing to render"), tr("The scene is not prepared yet."));
    return false;
  }
  if (finalRender_) {
    statusBar()->showMessage(tr("A final image is being rendered already."), 5000);
    return false;
  }
  const QFileInfo info(path);
  const QStringList formats = {QStringLiteral("png"), QStringLiteral("jpg"),  QStringLiteral("jpeg"),
                               QStringLiteral("tif"), QStringLiteral("tiff"), QStringLiteral("exr")};
  if (!formats.contains(info.suffix().toLower())) {
    showError(tr("Cannot render the final image"),
              tr("%1: choose a .png, .jpg, .tif or .exr file.").arg(QDir::toNativeSeparators(path)));
    return false;
  }
  if (!QFileInfo(info.absolutePath()).isDir()) {
    showError(tr("Cannot render the final image"),
              tr("%1: the folder %2 does not exist.")
                  .arg(info.fileName(), QDir::toNativeSeparators(info.absolutePath())));
    return false;
  }
  renderer_->setPaused(true);  // the processor is the final render's
  finalRender_ = new FinalRender(*prepared, info.absoluteFilePath(), maxSpp, this);
  renderFinalAct_->setEnabled(false);
  delete finalProgress_;
  finalProgress_ = new QProgressDialog(tr("Rendering the final image…"), tr("Cancel"), 0, 1000, this);
  finalProgress_->setWindowTitle(tr("Render Final Image"));
  finalProgress_->setWindowModality(Qt::NonModal);  // see the preparation's dialog
  finalProgress_->setMinimumDuration(interactive_ ? 0 : 1000000000);
  finalProgress_->setAutoClose(false);
  finalProgress_->setAutoReset(false);
  connect(finalProgress_, &QProgressDialog::canceled, finalRender_, &FinalRender::cancel);
  connect(finalRender_, &FinalRender::progressed, this, [this](const FinalRender::Progress& p) {
    const QString text =
        tr("Rendering the final image: %1 samples per pixel at most, estimated error %2 (target %3), %4 s")
            .arg(p.spp)
            .arg(p.estimatedError, 0, 'f', 4)
            .arg(p.noiseTarget, 0, 'f', 4)
            .arg(p.seconds, 0, 'f', 0);
    if (finalProgress_) {
      finalProgress_->setLabelText(text);
      finalProgress_->setValue(int(p.fraction * 1000));
    }
    statusBar()->showMessage(text);
  });
  connect(finalRender_, &FinalRender::finished, this, &MainWindow::onFinalRenderFinished);
  statusBar()->showMessage(tr("Rendering the final image…"));
  return true;
}

void MainWindow::onFinalRenderFinished(bool ok, const QString& message) {
  if (finalProgress_) {
    finalProgress_->hide();
    finalProgress_->deleteLater();
    finalProgress_ = nullptr;
  }
  const QString path = finalRender_ ? finalRender_->path() : QString();
  const bool cancelled = finalRender_ && finalRender_->cancelled();
  if (ok && finalRender_) showFinalImage(*finalRender_);
  if (finalRender_) finalRender_->deleteLater();
  finalRender_ = nullptr;
  renderer_->setPaused(false);
  renderFinalAct_->setEnabled(document_->isReady());
  if (ok) {
    stepsDock_->markExported(path);
    statusBar()->showMessage(finalShownText_);  // stays until the next edit
    statusBar()->setToolTip(message);
  } else if (cancelled) {
    statusBar()->showMessage(message, 8000);
  } else {
    showError(tr("Cannot write the final image"), message);
  }
  Q_EMIT finalImageFinished(ok, message);
}

void MainWindow::showFinalImage(const FinalRender& render) {
  const QImage& image = render.shownImage();
  if (image.isNull()) return;
  finalFigures_ = render.progress();
  finalLinear_ = render.composite();
  finalFile_ = QFileInfo(render.path()).fileName();
  viewport_->setFinalImage(image);
  showFinalTexts();
  onFrame();
}

// The final image's banner and status line, in the current language (again after a switch).
void MainWindow::showFinalTexts() {
  if (!viewport_->showsFinalImage()) return;
  const QSize size = viewport_->finalImage().size();
  const QString before = finalShownText_;
  finalShownText_ = tr("Final render shown (%1, %2 × %3); the next edit returns to the live preview.")
                        .arg(finalFile_)
                        .arg(size.width())
                        .arg(size.height());
  viewport_->setFinalCaption(tr("Final render (%1 × %2, saved as %3): shown until the next edit")
                                 .arg(size.width())
                                 .arg(size.height())
                                 .arg(finalFile_));
  if (!before.isEmpty() && statusBar()->currentMessage() == before)
    statusBar()->showMessage(finalShownText_);
}

void MainWindow::dropFinalImage() {
  if (finalShownText_.isEmpty() && !viewport_->showsFinalImage()) return;
  viewport_->setFinalImage(QImage());
  finalLinear_.reset();
  if (statusBar()->currentMessage() == finalShownText_) statusBar()->clearMessage();
  finalShownText_.clear();
  onFrame();
}

void MainWindow::exportSceneGltfDialog() {
  QString selected;
  const QString gltf = tr("glTF 2.0, separate files (*.gltf)"), glb = tr("glTF 2.0, binary (*.glb)");
  QString path = QFileDialog::getSaveFileName(this, tr("Export Scene as glTF"), QString(),
                                              gltf + QStringLiteral(";;") + glb, &selected);
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty())
    path += selected == glb ? QStringLiteral(".glb") : QStringLiteral(".gltf");
  exportSceneGltf(path);
}

bool MainWindow::exportSceneGltf(const QString& path) {
  const PreparedScene* prepared = document_->prepared();
  if (!document_->isReady() || !prepared) {
    showError(tr("Nothing to export"), tr("The scene is not prepared yet."));
    return false;
  }
  std::vector<std::string> warnings;
  const Status written =
      inlay::exportSceneGltf(*prepared, QDir::toNativeSeparators(path).toStdString(), &warnings);
  if (!written.ok()) {
    showError(tr("Cannot export the scene"), QString::fromStdString(written.error().message()));
    return false;
  }
  QString message = tr("Exported %1").arg(QDir::toNativeSeparators(path));
  if (!warnings.empty())
    message += QStringLiteral(" (") + QString::fromStdString(warnings.front()) + QStringLiteral(")");
  statusBar()->showMessage(message, 8000);
  return true;
}

void MainWindow::exportLayerDialog() {
  QString path = QFileDialog::getSaveFileName(
      this, tr("Export Shown Layer"), QString(),
      tr("PNG image (*.png)") + QStringLiteral(";;") + tr("JPEG image (*.jpg *.jpeg)") +
          QStringLiteral(";;") + tr("TIFF image (*.tif *.tiff)"));
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".png");
  exportShownLayer(path);
}

bool MainWindow::exportShownLayer(const QString& path) {
  const QImage image = viewport_->showsBefore() ? renderer_->photoImage()
                                                : renderer_->layerImage(viewport_->layer());
  if (image.isNull()) {
    showError(tr("Nothing to export"), tr("This layer has not been made yet."));
    return false;
  }
  // Through image_io as the composite is (atomic, TIFF without a Qt plugin, its messages), the
  // shown image's codes kept.
  const Status saved = saveImage(QDir::toNativeSeparators(path).toStdString(), linearFromSrgb8(image));
  if (!saved.ok()) {
    showError(tr("Cannot export the layer"), QString::fromStdString(saved.error().message()));
    return false;
  }
  statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(path)), 5000);
  return true;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() == 1 && urls.first().isLocalFile()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.size() != 1 || !urls.first().isLocalFile()) return;
  event->acceptProposedAction();
  const QString path = urls.first().toLocalFile();
  if (isModelFile(path)) {  // dropped beside the viewport: stands in the middle of the floor
    QMetaObject::invokeMethod(
        this, [this, path] { insertModelFile(path); }, Qt::QueuedConnection);
    return;
  }
  // After the drop has finished: maybeSave() may open a dialog.
  QMetaObject::invokeMethod(
      this,
      [this, path] {
        if (maybeSave()) openPath(path);
      },
      Qt::QueuedConnection);
}

void MainWindow::about() {
  QMessageBox::about(
      this, tr("About Inlay"),
      tr("<h3>Inlay %1</h3><p>Inserts synthetic objects into an ordinary photograph: a box room "
         "is fitted to the photo, its lights and reflectance are estimated, and a path tracer "
         "renders the objects into it (after Karsch et al., 2011).</p>")
          .arg(QString::fromLatin1(versionString())));
}

bool MainWindow::insertBuiltin(const QString& mesh) {
  const std::optional<Vec2> at = document_->freeStandingPointPx();
  if (!at) {
    statusBar()->showMessage(tr("There is no floor in the middle of the photo to stand an object on."),
                             5000);
    return false;
  }
  ObjectKeys keys;
  keys.mesh = mesh.toStdString();
  keys.basePx = *at;
  keys.heightM = 0.5;
  QString reason;
  if (!document_->insertObject(keys, &reason)) {
    statusBar()->showMessage(reason, 5000);
    return false;
  }
  return true;
}

void MainWindow::deleteSelected() {
  QString reason;
  // The selected mark, else the selected object.
  const std::optional<MarkRef> mark = document_->selectedMark();
  const bool ok = mark ? document_->removeMark(*mark, &reason)
                       : document_->removeObject(document_->selectedObject(), &reason);
  if (!ok) statusBar()->showMessage(reason, 5000);
}

void MainWindow::insertModelDialog() {
  const QString path =
      QFileDialog::getOpenFileName(this, tr("Insert Model"), QString(), modelFileFilter());
  if (!path.isEmpty()) insertModelFile(path);
}

bool MainWindow::insertModelFile(const QString& path, const std::optional<Vec2>& dropPx) {
  lastModelError_.clear();
  const QString name = QFileInfo(path).fileName();
  if (document_->scene().photo.empty()) {
    refuseModel(tr("%1: open a photo first; the model needs a room to stand in.").arg(name));
    return false;
  }
  if (!isModelFile(path)) {
    refuseModel(tr("%1: not a model file Inlay reads (%2).")
                    .arg(name, modelFileExtensions().join(QStringLiteral(", "))));
    return false;
  }
  // Read on a thread of its own: a large file must not freeze the window.
  auto result = std::make_shared<ModelLoadResult>();
  const double defaultHeight = defaultModelHeightM();
  QThread* loader = QThread::create(
      [result, path, defaultHeight] { *result = loadModelForInsert(path, defaultHeight); });
  loaders_ << loader;
  connect(loader, &QThread::finished, this, [this, loader, result, dropPx] {
    loaders_.removeOne(loader);
    loader->deleteLater();
    onModelLoaded(*result, dropPx);
  });
  statusBar()->showMessage(tr("Reading %1…").arg(name));
  loader->start();
  return true;
}

void MainWindow::onModelLoaded(const ModelLoadResult& result, const std::optional<Vec2>& dropPx) {
  if (!result.model) return refuseModel(result.error);
  addRecentFile(result.model->path, kRecentModelsKey);
  if (document_->state() == Document::State::Preparing) {
    waitingModels_.push_back({*result.model, dropPx});
    statusBar()->showMessage(tr("%1 goes in once the scene is prepared.").arg(result.model->name), 8000);
    return;
  }
  placeModel(*result.model, dropPx);
}

// Why a model at its own size (heightM high) cannot stand in the prepared room, if it cannot:
// taller than the ceiling, or wider than the room's longest side.
std::optional<QString> MainWindow::ownSizeMisfit(const ModelImport& model, double heightM) const {
  if (!document_->prepared()) return std::nullopt;
  const RoomBox& box = document_->prepared()->box;
  const double defaultM = defaultModelHeightM();
  if (box.ceilingM > 0 && heightM > box.ceilingM)
    return tr("%1 is %2 m high at its own size, taller than the room (%3 m): it was inserted "
              "%4 m high instead (change Height in Properties).")
        .arg(model.name)
        .arg(heightM, 0, 'f', 2)
        .arg(box.ceilingM, 0, 'f', 2)
        .arg(defaultM, 0, 'f', 2);
  const Eigen::AlignedBox3f b = model.mesh->bounds();
  const double units = meshHeightUnits(*model.mesh);
  if (!(units > 0)) return std::nullopt;
  const double widthM = heightM / units *
                        double(std::max(b.max().x() - b.min().x(), b.max().z() - b.min().z()));
  const double roomM = std::max(box.xRightM - box.xLeftM, box.zRearM - box.zBackM);
  if (roomM > 0 && widthM > roomM)
    return tr("%1 is %2 m wide at its own size, wider than the room (%3 m): it was inserted "
              "%4 m high instead (change Height in Properties).")
        .arg(model.name)
        .arg(widthM, 0, 'f', 2)
        .arg(roomM, 0, 'f', 2)
        .arg(defaultM, 0, 'f', 2);
  return std::nullopt;
}

bool MainWindow::placeModel(const ModelImport& model, std::optional<Vec2> dropPx) {
  const QString file = QFileInfo(model.path).fileName();
  const std::optional<Vec2> at = dropPx ? document_->supportPointNear(*dropPx)
                                        : document_->freeStandingPointPx();
  if (!at) {
    refuseModel(dropPx
                    ? tr("%1: there is no floor, table top or step under the drop point to stand it on.")
                          .arg(file)
                    : tr("%1: there is no floor in the middle of the photo to stand it on.").arg(file));
    return false;
  }
  ObjectKeys keys;
  keys.mesh = model.path.toStdString();
  keys.meshResolved = keys.mesh;
  keys.name = model.name.toStdString();
  keys.basePx = *at;
  keys.heightM = model.heightM;
  QStringList notes = model.notes;
  bool ownSize = model.ownSize;
  // A size the file states but the room cannot hold (a teapot taller than the ceiling, or
  // wider than the whole room) is a unit mistake of the file as much as 1 km is.
  if (ownSize) {
    if (const auto why = ownSizeMisfit(model, keys.heightM)) {
      notes << *why;
      keys.heightM = defaultModelHeightM();
      ownSize = false;
    }
  }
  // The file's own materials when it has any (a glTF's PBR values, an OBJ's MTL).
  const bool hasMaterials = !model.mesh->materials.empty() &&
                            model.mesh->materials.front().name != "default";
  keys.material.preset = hasMaterials ? "asset" : "diffuse";
  QString reason;
  if (!document_->insertObject(keys, model.mesh, &reason)) {
    refuseModel(tr("%1: %2").arg(file, engineText(reason)));
    return false;
  }
  QString message =
      ownSize ? tr("Inserted %1, %2 m high (its own size).").arg(model.name).arg(keys.heightM, 0, 'f', 2)
              : tr("Inserted %1, %2 m high.").arg(model.name).arg(keys.heightM, 0, 'f', 2);
  if (!notes.isEmpty()) message += QLatin1Char(' ') + notes.join(QLatin1Char(' '));
  statusBar()->showMessage(message, 12000);
  statusBar()->setToolTip(message);
  return true;
}

void MainWindow::refuseModel(const QString& text) {
  lastModelError_ = text;
  showError(tr("Cannot insert the model"), text);
}

void MainWindow::duplicateSelected() {
  QString reason;
  if (!document_->duplicateObject(document_->selectedObject(), &reason))
    statusBar()->showMessage(reason, 5000);
}

void MainWindow::toggleSelectedHidden() {
  const int i = document_->selectedObject();
  QString reason;
  const bool hidden = i >= 0 && i < document_->objectCount() &&
                      document_->scene().objects[size_t(i)].hidden;
  if (!document_->setObjectHidden(i, !hidden, &reason)) statusBar()->showMessage(reason, 5000);
}

void MainWindow::renameSelected() {
  // In place, in the Scene list (the undoable rename happens when the editor closes).
  if (!sceneDock_->editName(document_->selectedObject()))
    statusBar()->showMessage(tr("Select an object to rename."), 5000);
}

void MainWindow::addRecentFile(const QString& path, const char* key) {
  QSettings settings;
  QStringList files = settings.value(QLatin1String(key)).toStringList();
  files.removeAll(path);
  files.prepend(path);
  while (files.size() > kMaxRecentFiles) files.removeLast();
  settings.setValue(QLatin1String(key), files);
  rebuildRecentMenu();
}

// Scenes and photos first (choosing one opens it), then the models inserted lately (choosing
// one inserts it again into the open scene).
void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  const QSettings settings;
  const QStringList files = settings.value(QLatin1String(kRecentKey)).toStringList();
  const QStringList models = settings.value(QLatin1String(kRecentModelsKey)).toStringList();
  for (int i = 0; i < files.size(); ++i) {
    const QString& f = files[i];
    QAction* a =
        recentMenu_->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(f).fileName()));
    a->setStatusTip(QDir::toNativeSeparators(f));
    connect(a, &QAction::triggered, this, [this, f] {
      if (maybeSave()) openPath(f);
    });
  }
  if (!models.isEmpty()) {
    recentMenu_->addSection(tr("Models"));
    for (const QString& f : models) {
      QAction* a = recentMenu_->addAction(tr("Insert %1").arg(QFileInfo(f).fileName()));
      a->setData(f);
      a->setStatusTip(QDir::toNativeSeparators(f));
      a->setEnabled(!document_->scene().photo.empty());
      connect(a, &QAction::triggered, this, [this, f] { insertModelFile(f); });
    }
  }
  recentMenu_->setEnabled(!files.isEmpty() || !models.isEmpty());
}

void MainWindow::setLanguage(const QString& code) {
  QSettings().setValue(QStringLiteral("language"), code);
  // The choice made here wins over INLAY_LANG and the system's; installing sends every widget a
  // QEvent::LanguageChange, and each retranslates itself.
  installTranslators(code.isEmpty() ? QLocale::system().name().section(QLatin1Char('_'), 0, 0) : code);
}

QAction* MainWindow::toolAction(int tool) const {
  return tool >= 0 && tool < toolActs_.size() ? toolActs_[tool] : nullptr;
}

bool MainWindow::offerRecovery() {
  const std::optional<Autosaver::Recovery> r = Autosaver::pending();
  if (!r) return false;
  if (!interactive_) return true;
  const QString what = r->originalPath.isEmpty() ? tr("a new scene")
                                                 : QDir::toNativeSeparators(r->originalPath);
  auto* box =
      new QMessageBox(QMessageBox::Question, tr("Restore unsaved work?"),
                      tr("Inlay did not close properly. Unsaved work on %1 was kept at %2. Restore it?")
                          .arg(what, QLocale().toString(r->saved.toLocalTime(), QLocale::ShortFormat)),
                      QMessageBox::NoButton, this);
  box->setObjectName(QStringLiteral("recoveryQuestion"));
  QPushButton* restore = box->addButton(tr("&Restore"), QMessageBox::AcceptRole);
  box->addButton(tr("&Discard"), QMessageBox::DestructiveRole);
  box->setDefaultButton(restore);
  box->setAttribute(Qt::WA_DeleteOnClose);
  connect(box, &QMessageBox::buttonClicked, this, [this, restore](QAbstractButton* b) {
    if (b == restore) restoreRecovery();
    else if (const std::optional<Autosaver::Recovery> offered = Autosaver::pending())
      Autosaver::discard(*offered);
  });
  box->open();
  return true;
}

bool MainWindow::restoreRecovery() {
  const std::optional<Autosaver::Recovery> r = Autosaver::pending();
  if (!r) return false;
  QString error;
  if (!document_->restoreRecovery(r->scenePath, r->originalPath, &error)) {
    showError(tr("Cannot restore the unsaved work"), error);
    return false;
  }
  // The work is this studio's now: written to its own files before the old ones go.
  autosaver_->markDirty();
  if (autosaver_->saveNow()) Autosaver::discard(*r);
  statusBar()->showMessage(tr("Restored the unsaved work."), 6000);
  return true;
}

bool MainWindow::maybeSave() {
  if (!interactive_ || document_->undoStack()->isClean()) return true;
  const auto answer = QMessageBox::warning(
      this, tr("Inlay"), tr("The scene has unsaved changes. Save them?"),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

bool MainWindow::settleFinalRender(const QString& proceedText, const std::function<void()>& proceed) {
  // None, or cancelled and writing its file (that ends by itself; the destructor waits for it).
  if (!finalRender_ || finalRender_->cancelled()) return true;
  if (!interactive_) {
    finalRender_->cancel();
    return true;
  }
  delete finalQuestion_;  // asked again (a second close): the newest question's action wins
  finalQuestion_ = new QMessageBox(
      QMessageBox::Question, tr("Render Final Image"),
      tr("The final image %1 is still being rendered (%2 % done). Cancel the render? Nothing "
         "is written then, and an earlier file of that name stays as it was.")
          .arg(QFileInfo(finalRender_->path()).fileName())
          .arg(qRound(finalRender_->progress().fraction * 100)),
      QMessageBox::NoButton, this);
  finalQuestion_->setObjectName(QStringLiteral("finalRenderQuestion"));
  QPushButton* stop = finalQuestion_->addButton(proceedText, QMessageBox::DestructiveRole);
  stop->setObjectName(QStringLiteral("cancelRenderButton"));
  QPushButton* keep = finalQuestion_->addButton(tr("Keep Rendering"), QMessageBox::RejectRole);
  keep->setObjectName(QStringLiteral("keepRenderingButton"));
  finalQuestion_->setDefaultButton(keep);
  finalQuestion_->setEscapeButton(keep);
  finalQuestion_->setAttribute(Qt::WA_DeleteOnClose);
  connect(finalQuestion_, &QMessageBox::buttonClicked, this, [this, stop, proceed](QAbstractButton* b) {
    if (b != stop) return;
    if (finalRender_) finalRender_->cancel();
    // After the box has closed: `proceed` may close this window or open another scene.
    QMetaObject::invokeMethod(this, proceed, Qt::QueuedConnection);
  });
  // The render may end while the question is open: the question is moot then.
  connect(this, &MainWindow::finalImageFinished, finalQuestion_,
          [box = finalQuestion_.data()] { box->done(QMessageBox::Cancel); });
  finalQuestion_->open();
  return false;
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!settleFinalRender(tr("Cancel the Render and Close"), [this] { close(); })) {
    event->ignore();
    return;
  }
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  autosaver_->discardOwn();  // saved, or the user chose to discard
  QSettings settings;
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState());
  event->accept();
}

}  // namespace inlay::studio
