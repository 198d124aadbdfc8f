#include "log_dock.h"
#include "engine_text.h"
#include "stage_text.h"

#include <QEvent>
#include <QFontDatabase>
#include <QPlainTextEdit>
#include <QTime>

namespace inlay::studio {

LogDock::LogDock(Document* document, QWidget* parent)
    : QDockWidget(parent), document_(document), log_(new QPlainTextEdit(this)) {
  setObjectName(QStringLiteral("logDock"));
  log_->setReadOnly(true);
  log_->setMaximumBlockCount(5000);               // a long session's log stays small
  log_->setLineWrapMode(QPlainTextEdit::NoWrap);  // one line per stage, as a table reads
  log_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  setWidget(log_);
  connect(document_, &Document::changed, this, &LogDock::onDocumentChanged);
  retranslate();
}

QString LogDock::text() const { return log_->toPlainText(); }

void LogDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

void LogDock::retranslate() { setWindowTitle(tr("Log")); }

void LogDock::onDocumentChanged(const ChangeEvent& event) {
  if (!event.has(ChangeEvent::PrepareFinished)) return;
  const QString now = QTime::currentTime().toString(QStringLiteral("HH:mm:ss"));
  const PreparedScene* prepared = document_->prepared();
  if (document_->state() == Document::State::Failed) {
    log_->appendPlainText(
        tr("%1 The scene could not be prepared: %2").arg(now, engineText(document_->prepareError())));
    return;
  }
  if (document_->state() != Document::State::Ready || !prepared)
    return;  // cancelled: a newer job follows
  double seconds = 0;
  for (const StageRecord& s : prepared->stages) seconds += s.seconds;
  QStringList lines{tr("%1 Prepared the scene in %2 s:").arg(now).arg(seconds, 0, 'f', 2)};
  // The warnings first: the stages, one short line each, end the block where the view scrolls.
  for (const QString& w : document_->warnings())
    lines << QStringLiteral("  ") + tr("warning: %1").arg(engineText(w));
  for (const StageRecord& s : prepared->stages) lines << QStringLiteral("  ") + stageLine(s);
  log_->appendPlainText(lines.join(QLatin1Char('\n')));
}

}  // namespace inlay::studio
