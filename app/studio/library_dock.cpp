#include "library_dock.h"

#include "inlay/engine/model_library.h"

#include <QCoreApplication>
#include <QEvent>
#include <QIcon>
#include <QLabel>
#include <QMimeData>
#include <QPixmap>
#include <QUrl>
#include <QVBoxLayout>

namespace inlay::studio {
namespace {

constexpr int kRoleFile = Qt::UserRole + 1;   // the .glb's absolute path
constexpr int kRoleTitle = Qt::UserRole + 2;  // the English title from library.json
constexpr int kRoleSize = Qt::UserRole + 3;   // QVariantList: width, depth, height (m)

// The bundled pieces' titles, for lupdate; looked up at run time by translatedTitle().
[[maybe_unused]] const char* const kTitles[] = {
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Chair"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Armchair"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Sofa"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Coffee table"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Dining table"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Stool"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Floor lamp"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Table lamp"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Vase"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Potted plant"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Bookshelf"),
    QT_TRANSLATE_NOOP("inlay::studio::LibraryDock", "Rug"),
};

}  // namespace

QStringList LibraryList::mimeTypes() const { return {QStringLiteral("text/uri-list")}; }

QMimeData* LibraryList::mimeData(const QList<QListWidgetItem*>& items) const {
  QList<QUrl> urls;
  for (const QListWidgetItem* item : items)
    urls.push_back(QUrl::fromLocalFile(item->data(kRoleFile).toString()));
  if (urls.isEmpty()) return nullptr;
  auto* mime = new QMimeData;
  mime->setUrls(urls);  // text/uri-list
  return mime;
}

LibraryDock::LibraryDock(QWidget* parent, const QString& modelsDir)
    : QDockWidget(parent),
      modelsDir_(modelsDir),
      list_(new LibraryList(this)),
      message_(new QLabel(this)) {
  setObjectName(QStringLiteral("libraryDock"));
  list_->setViewMode(QListView::IconMode);
  list_->setIconSize(QSize(96, 96));
  list_->setGridSize(QSize(116, 128));
  list_->setResizeMode(QListView::Adjust);
  list_->setMovement(QListView::Static);
  list_->setWordWrap(true);
  list_->setUniformItemSizes(true);
  list_->setSelectionMode(QAbstractItemView::SingleSelection);
  list_->setDragEnabled(true);
  list_->setDragDropMode(QAbstractItemView::DragOnly);
  message_->setWordWrap(true);
  auto* box = new QWidget(this);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(message_);
  layout->addWidget(list_);
  setWidget(box);
  connect(list_, &QListWidget::itemActivated, this,
          [this](QListWidgetItem* item) { Q_EMIT pieceActivated(item->data(kRoleFile).toString()); });
  load();
  retranslate();
}

QString LibraryDock::translatedTitle(const QString& englishTitle) {
  return QCoreApplication::translate("inlay::studio::LibraryDock", englishTitle.toUtf8().constData());
}

void LibraryDock::load() {
  const std::string dir = modelsDir_.isEmpty() ? modelLibraryDir() : modelsDir_.toStdString();
  if (dir.empty()) {
    missing_ = true;
    return;
  }
  auto pieces = loadModelLibrary(dir);
  if (!pieces) {
    problem_ = QString::fromStdString(pieces.error().message());
    return;
  }
  for (const LibraryPiece& p : *pieces) {
    auto* item =
        new QListWidgetItem(QIcon(QPixmap(QString::fromStdString(p.thumbnail))), QString(), list_);
    item->setData(kRoleFile, QString::fromStdString(p.file));
    item->setData(kRoleTitle, QString::fromStdString(p.title));
    item->setData(kRoleSize, QVariantList{p.sizeM.x(), p.sizeM.y(), p.sizeM.z()});
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled);
  }
}

void LibraryDock::retranslate() {
  setWindowTitle(tr("Library"));
  const QString problem =
      missing_
          ? tr("no library.json in $INLAY_MODELS_DIR, <prefix>/share/inlay/models or resources/models")
          : problem_;
  message_->setVisible(!problem.isEmpty());
  if (!problem.isEmpty()) message_->setText(tr("The model library could not be shown: %1").arg(problem));
  for (int i = 0; i < list_->count(); ++i) {
    QListWidgetItem* item = list_->item(i);
    const QString title = translatedTitle(item->data(kRoleTitle).toString());
    const QVariantList s = item->data(kRoleSize).toList();
    item->setText(title);
    item->setToolTip(tr("%1\n%2 × %3 × %4 m (width × depth × height)\nDrag it into the photo.")
                         .arg(title)
                         .arg(s.value(0).toDouble(), 0, 'f', 2)
                         .arg(s.value(1).toDouble(), 0, 'f', 2)
                         .arg(s.value(2).toDouble(), 0, 'f', 2));
  }
}

void LibraryDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

}  // namespace inlay::studio
