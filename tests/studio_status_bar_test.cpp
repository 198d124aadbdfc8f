// The status bar's messages stay readable: at the workflow tests' 1280 × 800 and in narrower
// windows, in English, German and French, a long transient message (the final render's
// progress, a model's notes, the final image's line) wraps onto more lines instead of being cut
// off where the permanent fields begin; no line is wider than the message's room, the message
// never runs under a field, every field's own text fits, and only when even kMaxLines are not
// enough does the message end with "…", its whole text then in the tooltip. Pictures of the
// bar go to studio_status_bar_artifacts/ in the build tree.
#include "i18n.h"
#include "main_window.h"
#include "status_bar.h"

#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>

#include "studio_test_support.h"
#include "studio_workflow_steps.h"

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::test;

namespace {

// Long messages the studio shows, in the current language.
QStringList longMessages() {
  auto tr = [](const char* context, const char* text) {
    return QCoreApplication::translate(context, text);
  };
  return {
      tr("inlay::studio::MainWindow",
         "Rendering the final image: %1 samples per pixel at most, estimated error %2 (target %3), %4 s")
          .arg(128)
          .arg(0.0123, 0, 'f', 4)
          .arg(0.004, 0, 'f', 4)
          .arg(37),
      tr("inlay::studio::ModelImportText",
         "%1's image textures are not rendered: Inlay uses its materials' base colour, metallic and "
         "roughness values.")
          .arg(QStringLiteral("walnut_sideboard_catalogue_2024.glb")),
      tr("inlay::studio::MainWindow",
         "Final render shown (%1, %2 × %3); the next edit returns to the live preview.")
          .arg(QStringLiteral("lounge_with_armchair_final.png"))
          .arg(4000)
          .arg(3000),
  };
}

// What is wrong with the bar showing `text` now (empty: nothing). `whole`: the message must be
// shown without "…".
QString problemsOf(const StatusBar* bar, const QString& text, bool whole) {
  QStringList problems;
  const StatusMessage* m = bar->message();
  if (m->text() != text) return QStringLiteral("the message is not shown");
  const QFontMetrics fm = m->fontMetrics();
  const QStringList lines = m->shownLines();
  if (lines.isEmpty() || lines.size() > StatusMessage::kMaxLines)
    problems << QStringLiteral("%1 lines").arg(lines.size());
  for (const QString& line : lines)
    if (fm.horizontalAdvance(line) > m->contentsRect().width())
      problems << QStringLiteral("\"%1\" is wider than %2 px").arg(line).arg(m->contentsRect().width());
  if (m->height() < int(lines.size()) * fm.lineSpacing() || m->geometry().bottom() >= bar->height())
    problems << QStringLiteral("%1 lines in %2 px of a bar %3 px high")
                    .arg(lines.size())
                    .arg(m->height())
                    .arg(bar->height());
  if (whole && m->elided()) problems << QStringLiteral("elided: %1").arg(lines.join(QLatin1Char('|')));
  if (!m->elided() && lines.join(QLatin1Char(' ')).simplified() != text.simplified())
    problems << QStringLiteral("shown \"%1\"").arg(lines.join(QLatin1Char('|')));
  if (m->elided() && !m->toolTipText().startsWith(text))
    problems << QStringLiteral("elided, but the tooltip is \"%1\"").arg(m->toolTipText());
  for (const QLabel* field : bar->findChildren<QLabel*>()) {
    if (field->isHidden()) continue;
    if (field->geometry().intersects(m->geometry()))
      problems << QStringLiteral("the message runs under \"%1\"").arg(field->text());
    if (field->fontMetrics().horizontalAdvance(field->text()) > field->contentsRect().width())
      problems << QStringLiteral("the field \"%1\" is cut off").arg(field->text());
    if (field->geometry().right() >= bar->width())
      problems << QStringLiteral("the field \"%1\" is outside the bar").arg(field->text());
  }
  const int room = std::min(StatusBar::kMinMessageWidth, bar->width() / 2);
  if (m->width() < room) problems << QStringLiteral("the message has only %1 px").arg(m->width());
  return problems.join(QStringLiteral("; "));
}

}  // namespace

class StudioStatusBarTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void longMessagesStayReadable();
  void cleanupTestCase() { removeTranslators(); }
};

void StudioStatusBarTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_status_bar_test"));
  QSettings().clear();
}

void StudioStatusBarTest::longMessagesStayReadable() {
  MainWindow window;
  QVERIFY(showForWorkflow(window));  // 1280 × 800
  auto* bar = qobject_cast<StatusBar*>(window.statusBar());
  QVERIFY(bar);
  StepLog shots(QStringLiteral("studio_status_bar_artifacts"));
  for (const char* language : {"en", "de", "fr"}) {
    if (QByteArray(language) == "en") removeTranslators();
    else QVERIFY2(installTranslators(QLatin1String(language)), language);
    const QStringList messages = longMessages();
    if (QByteArray(language) != "en")  // the messages are in the catalogue
      QVERIFY2(messages[0].startsWith(QStringLiteral("Rendering")) == false, qPrintable(messages[0]));
    for (const int width : {1280, 900, 640}) {
      window.resize(width, 800);
      QTRY_COMPARE(bar->width(), window.width());
      for (int i = 0; i < messages.size(); ++i) {
        bar->showMessage(messages[i]);
        QString problems;
        // At 1280 px every message is shown whole; narrower, the bar may elide the end.
        QTRY_VERIFY2(
            (problems = problemsOf(bar, messages[i], width >= 1280)).isEmpty(),
            qPrintable(QStringLiteral("%1 at %2 px: %3").arg(language).arg(width).arg(problems)));
        QVERIFY(
            shots.shot(bar, QStringLiteral("status_%1_%2px_%3").arg(language).arg(width).arg(i + 1)));
      }
      // The bar keeps its height with and without a message: the viewport never moves.
      const int barHeight = bar->height();
      bar->clearMessage();
      QTRY_VERIFY(bar->message()->shownLines().isEmpty());
      QCOMPARE(bar->height(), barHeight);
    }
  }
  // The whole window at 1280 × 800 in French with the longest message.
  window.resize(1280, 800);
  bar->showMessage(longMessages()[1]);
  QTRY_VERIFY(problemsOf(bar, longMessages()[1], true).isEmpty());
  QVERIFY(shots.shot(&window, QStringLiteral("window_fr_1280px")));
}

QTEST_MAIN(StudioStatusBarTest)
#include "studio_status_bar_test.moc"
