// The Steps dock on a freshly opened photo (the bundled example's photo, estimated from
// scratch): every step's title, state and button fit (no line of a wrapped state cut off, no
// squeezed title or button) at the default window size and in a narrow dock, in English,
// German and French; the Camera Response dock's notes fit as well, and the preparation's
// progress dialog counts the seconds with a busy bar while a stage reports no fraction. The dock's pictures go to studio_steps_dock_artifacts/ in the build tree.
#include "document.h"
#include "i18n.h"
#include "main_window.h"
#include "steps_dock.h"

#include <QDockWidget>
#include <QLabel>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

#include "studio_test_support.h"
#include "studio_workflow_steps.h"

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::test;

namespace {

// The height `label`'s text takes wrapped at the label's width (QLabel::heightForWidth never
// answers less than the label's minimum height, so it cannot tell a gap).
int neededHeight(const QLabel* label) {
  const QMargins m = label->contentsMargins();
  return label->fontMetrics()
             .boundingRect(QRect(0, 0, label->width() - m.left() - m.right(), 1 << 20),
                           Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, label->text())
             .height() +
         m.top() + m.bottom();
}

// What does not fit in the dock now (empty: everything does).
QString clipped(const StepsDock* steps) {
  const QWidget* body = steps->widget();
  QStringList problems;
  for (int i = 1; i <= StepsDock::kStepCount; ++i) {
    const auto* state = body->findChild<QLabel*>(QStringLiteral("stepState%1").arg(i));
    const auto* title = body->findChild<QLabel*>(QStringLiteral("stepTitle%1").arg(i));
    const auto* button = body->findChild<QPushButton*>(QStringLiteral("stepButton%1").arg(i));
    if (!state || !title || !button) return QStringLiteral("step %1's widgets are missing").arg(i);
    if (state->height() < neededHeight(state))
      problems << QStringLiteral("step %1's state \"%2\" needs %3 px, has %4")
                      .arg(i)
                      .arg(state->text())
                      .arg(neededHeight(state))
                      .arg(state->height());
    if (state->height() > neededHeight(state) + state->fontMetrics().lineSpacing())
      problems << QStringLiteral("step %1's state \"%2\" has %3 px, needs only %4 (a gap)")
                      .arg(i)
                      .arg(state->text())
                      .arg(state->height())
                      .arg(neededHeight(state));
    if (state->geometry().bottom() >= body->height() || state->geometry().right() >= body->width())
      problems << QStringLiteral("step %1's state is outside the dock").arg(i);
    const auto* next = body->findChild<QLabel*>(QStringLiteral("stepTitle%1").arg(i + 1));
    const int number = title->fontMetrics().lineSpacing() * 2;
    if (next && next->geometry().top() - state->geometry().bottom() > number)
      problems << QStringLiteral("a gap of %1 px after step %2")
                      .arg(next->geometry().top() - state->geometry().bottom())
                      .arg(i);
    if (title->width() < title->sizeHint().width())
      problems << QStringLiteral("step %1's title \"%2\" squeezed").arg(i).arg(title->text());
    if (button->isVisible() &&
        (button->width() < button->sizeHint().width() || button->geometry().right() >= body->width()))
      problems << QStringLiteral("step %1's button \"%2\" clipped").arg(i).arg(button->text());
  }
  return problems.join(QStringLiteral("; "));
}

}  // namespace

class StudioStepsDockTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void everyStepFitsInEveryLanguage();
  void cleanupTestCase() { removeTranslators(); }
};

void StudioStepsDockTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_steps_dock_test"));
  QSettings().clear();
}

void StudioStepsDockTest::everyStepFitsInEveryLanguage() {
  const QString photo = examplePhoto();
  if (photo.isEmpty()) QSKIP("the bundled example is not found");
  MainWindow window;
  QVERIFY(showForWorkflow(window));  // 1280 × 800, the workflow tests' window
  QVERIFY(window.openPath(photo));
  {
    // The preparation's dialog: a busy bar until a stage reports a fraction, and the seconds
    // ticking (the lighting stage reports only its end: a bar at 0 % for a minute looked frozen).
    QPointer<QProgressDialog> dialog = window.findChild<QProgressDialog*>();
    QVERIFY(dialog);
    QCOMPARE(dialog->maximum(), 0);
    QVERIFY2(dialog->labelText().endsWith(QStringLiteral(" 0 s")), qPrintable(dialog->labelText()));
    QTRY_VERIFY2_WITH_TIMEOUT(window.document()->state() != Document::State::Preparing ||
                                  (dialog && !dialog->labelText().endsWith(QStringLiteral(" 0 s"))),
                              qPrintable(dialog ? dialog->labelText() : QString()), waitMs(120000));
  }
  QVERIFY2(waitReady(window.document(), waitMs(120000)), qPrintable(window.document()->prepareError()));
  StepsDock* steps = window.stepsDock();
  QVERIFY(steps->isVisible());
  QVERIFY2(steps->stateText(StepsDock::Room).endsWith(QStringLiteral("the room's corners")),
           qPrintable(steps->stateText(StepsDock::Room)));
  StepLog shots(QStringLiteral("studio_steps_dock_artifacts"));
  const int defaultWidth = steps->width();
  for (const char* language : {"en", "de", "fr"}) {
    if (QByteArray(language) == "en") removeTranslators();
    else QVERIFY2(installTranslators(QLatin1String(language)), language);
    // The dock has retranslated itself (QEvent::LanguageChange is delivered by the event loop).
    QTRY_COMPARE(steps->windowTitle(), StepsDock::tr("Steps"));
    for (const bool narrow : {false, true}) {
      // Narrow: floated and made as narrow as it goes (its own minimum width).
      steps->setFloating(narrow);
      if (narrow) steps->resize(120, 420);
      else window.resizeDocks({steps}, {defaultWidth}, Qt::Horizontal);
      QString problems;
      QTRY_VERIFY2(
          (problems = clipped(steps)).isEmpty(),
          qPrintable(QStringLiteral("%1 at %2 px: %3").arg(language).arg(steps->width()).arg(problems)));
      QVERIFY(shots.shot(steps, QStringLiteral("steps_%1_%2px").arg(language).arg(steps->width())));
    }
  }
  steps->setFloating(false);
  // The Camera Response dock's notes below its curve are not cut off either.
  auto* info = window.findChild<QLabel*>(QStringLiteral("responseInfo"));
  QVERIFY(info && !info->text().isEmpty());
  // ... and that dock follows the switch to French as well.
  QCOMPARE(window.findChild<QDockWidget*>(QStringLiteral("responseDock"))->windowTitle(),
           QStringLiteral("Réponse de l'appareil"));
  QTRY_VERIFY2(
      info->height() >= neededHeight(info) && info->geometry().bottom() < info->parentWidget()->height(),
      qPrintable(QStringLiteral("%1 px for %2 px of \"%3\"")
                     .arg(info->height())
                     .arg(neededHeight(info))
                     .arg(info->text())));
  // The toolbar's buttons take their French texts' widths once the relayout after the switch
  // has run (a screenshot taken before it cuts "Dessus de table ou marche" at both ends).
  auto* toolbar = window.findChild<QToolBar*>(QStringLiteral("mainToolBar"));
  QVERIFY(toolbar);
  auto squeezed = [toolbar] {
    QStringList out;
    for (const QToolButton* b : toolbar->findChildren<QToolButton*>())
      if (b->isVisible() && b->width() < b->sizeHint().width()) out << b->text();
    return out.join(QStringLiteral(", "));
  };
  QTRY_VERIFY2(squeezed().isEmpty(), qPrintable(squeezed()));
  QVERIFY(shots.shot(&window, QStringLiteral("window_fr")));
}

QTEST_MAIN(StudioStepsDockTest)
#include "studio_steps_dock_test.moc"
