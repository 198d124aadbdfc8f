// The Library dock (app/studio/library_dock.h) on the bundled model library: one thumbnail per
// piece of library.json with its title, a drag of a piece carries its .glb as a file URL
// (text/uri-list), titles follow the language, and a folder without a library says so instead
// of showing an empty list. Offscreen; needs nothing from ../shared.
#include "i18n.h"
#include "library_dock.h"

#include "inlay/engine/model_library.h"

#include <QFileInfo>
#include <QLabel>
#include <QMimeData>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace inlay;
using namespace inlay::studio;

namespace {

QString modelsDir() {
  return qEnvironmentVariable("INLAY_SOURCE_DIR") + QStringLiteral("/resources/models");
}

}  // namespace

class LibraryDockTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void showsEveryPieceWithItsThumbnail() {
    auto pieces = loadModelLibrary(modelsDir().toStdString());
    QVERIFY2(pieces.ok(), pieces.ok() ? "" : pieces.error().message().c_str());
    LibraryDock dock(nullptr, modelsDir());
    QCOMPARE(dock.list()->count(), int(pieces->size()));
    QVERIFY(dock.list()->count() >= 12);
    for (int i = 0; i < dock.list()->count(); ++i) {
      QListWidgetItem* item = dock.list()->item(i);
      QCOMPARE(item->text(), QString::fromStdString((*pieces)[size_t(i)].title));
      QVERIFY2(!item->icon().isNull(), qPrintable(item->text()));
      QVERIFY(item->flags() & Qt::ItemIsDragEnabled);
      QVERIFY(item->toolTip().contains(QStringLiteral(" m ")));
    }
  }

  void aDragCarriesThePiecesFileAsAUrl() {
    LibraryDock dock(nullptr, modelsDir());
    QVERIFY(dock.list()->count() > 0);
    QCOMPARE(dock.list()->mimeTypes(), QStringList{QStringLiteral("text/uri-list")});
    const std::unique_ptr<QMimeData> mime(dock.list()->mimeData({dock.list()->item(0)}));
    QVERIFY(mime);
    QVERIFY(mime->hasFormat(QStringLiteral("text/uri-list")));
    QCOMPARE(mime->urls().size(), 1);
    const QUrl url = mime->urls().front();
    QVERIFY(url.isLocalFile());
    QVERIFY2(QFileInfo(url.toLocalFile()).isFile(), qPrintable(url.toString()));
    QVERIFY(url.toLocalFile().endsWith(QStringLiteral(".glb")));
    QSignalSpy activated(&dock, &LibraryDock::pieceActivated);
    Q_EMIT dock.list()->itemActivated(dock.list()->item(0));
    QCOMPARE(activated.size(), 1);
    QCOMPARE(activated.front().front().toString(), url.toLocalFile());
  }

  void titlesFollowTheLanguage() {
    LibraryDock dock(nullptr, modelsDir());
    QListWidgetItem* chair = nullptr;
    for (int i = 0; i < dock.list()->count(); ++i)
      if (dock.list()->item(i)->text() == QStringLiteral("Chair")) chair = dock.list()->item(i);
    QVERIFY(chair);
    // QApplication posts LanguageChange to the top-level widgets: wait for it.
    QVERIFY(installTranslators(QStringLiteral("de")));
    QTRY_COMPARE(chair->text(), QStringLiteral("Stuhl"));
    QCOMPARE(dock.windowTitle(), QStringLiteral("Bibliothek"));
    QVERIFY(installTranslators(QStringLiteral("fr")));
    QTRY_COMPARE(chair->text(), QStringLiteral("Chaise"));
    removeTranslators();
    QTRY_COMPARE(chair->text(), QStringLiteral("Chair"));
  }

  void aFolderWithoutALibrarySaysSo() {
    QTemporaryDir empty;
    LibraryDock dock(nullptr, empty.path());
    QCOMPARE(dock.list()->count(), 0);
    const QLabel* message = dock.findChild<QLabel*>();
    QVERIFY(message && !message->isHidden());
    QVERIFY2(message->text().contains(QStringLiteral("library.json")), qPrintable(message->text()));
  }
};

QTEST_MAIN(LibraryDockTest)
#include "studio_library_dock_test.moc"
