#include "steps_dock.h"

#include "document.h"
#include "wrapped_labels.h"

#include <QAction>
#include <QEvent>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpacerItem>

namespace inlay::studio {

StepsDock::StepsDock(Document* document, const Actions& actions, QWidget* parent)
    : QDockWidget(parent), document_(document), actions_(actions) {
  setObjectName(QStringLiteral("stepsDock"));
  auto* body = new QWidget(this);
  auto* grid = new QGridLayout(body);
  grid->setContentsMargins(6, 4, 6, 4);
  grid->setVerticalSpacing(2);
  grid->setColumnStretch(1, 1);
  for (int i = 0; i < kStepCount; ++i) {
    Row& r = rows_[size_t(i)];
    r.number = new QLabel(QString::number(i + 1), body);
    r.number->setAlignment(Qt::AlignCenter);
    r.number->setFixedSize(22, 22);
    r.title = new QLabel(body);
    r.state = new QLabel(body);
    r.state->setWordWrap(true);
    r.state->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    r.state->setContentsMargins(0, 0, 0, 6);  // a little air before the next step
    r.state->setObjectName(QStringLiteral("stepState%1").arg(i + 1));
    r.title->setObjectName(QStringLiteral("stepTitle%1").arg(i + 1));
    r.button = new QPushButton(body);
    r.button->setObjectName(QStringLiteral("stepButton%1").arg(i + 1));
    connect(r.button, &QPushButton::clicked, this, [this, i] {
      if (QAction* a = rows_[size_t(i)].action) a->trigger();
    });
    // The title with the step's button on its line, the state below across the dock's width.
    grid->addWidget(r.number, 2 * i, 0, Qt::AlignTop);
    grid->addWidget(r.title, 2 * i, 1);
    grid->addWidget(r.button, 2 * i, 2);
    grid->addWidget(r.state, 2 * i + 1, 1, 1, 2);
  }
  // The rows at their own heights, the dock's spare height below the last one.
  grid->addItem(new QSpacerItem(0, 0, QSizePolicy::Minimum, QSizePolicy::Expanding), 2 * kStepCount, 0);
  grid->setRowStretch(2 * kStepCount, 1);
  setWidget(body);
  QList<QLabel*> states;  // each as tall as its text wrapped at the dock's width
  for (const Row& r : rows_) states << r.state;
  fitter_ = new WrappedLabelFitter(body, states);
  for (QAction* a : {actions_.openPhoto, actions_.acceptBox, actions_.outlineLight, actions_.insertModel,
                     actions_.renderFinal})
    if (a) connect(a, &QAction::changed, this, &StepsDock::refresh);
  connect(document_, &Document::changed, this, &StepsDock::onDocumentChanged);
  retranslate();
}

void StepsDock::onDocumentChanged(const ChangeEvent& event) {
  if (event.has(ChangeEvent::SceneReplaced)) {
    exportedPath_.clear();
    announced_ = false;
  }
  refresh();
}

void StepsDock::markExported(const QString& path) {
  exportedPath_ = path;
  refresh();
}

int StepsDock::currentStep() const {
  for (int i = 0; i < kStepCount; ++i)
    if (!done_[size_t(i)]) return i;
  return kStepCount;
}

QString StepsDock::stateText(Step step) const { return rows_[size_t(step)].state->text(); }

void StepsDock::showRow(Step step, bool done, const QString& state, const QString& buttonText,
                        QAction* action) {
  Row& r = rows_[size_t(step)];
  done_[size_t(step)] = done;
  r.state->setText(state);
  r.action = done ? nullptr : action;
  r.button->setText(buttonText);
  r.button->setVisible(r.action != nullptr);
  r.button->setEnabled(r.action && r.action->isEnabled());
  if (r.action) r.button->setToolTip(r.action->statusTip());
  r.number->setText(done ? QStringLiteral("✓") : QString::number(int(step) + 1));
}

// Every row's state from the document, then which one is current.
void StepsDock::refresh() {
  const SceneDoc& doc = document_->scene();
  const bool photo = !doc.photo.empty();
  const bool preparing = document_->state() == Document::State::Preparing;
  // 1 Room.
  if (!photo) showRow(Room, false, tr("no photo yet"), tr("Open Photo…"), actions_.openPhoto);
  else if (document_->backWallIsUsers()) showRow(Room, true, tr("the box is yours"), {}, nullptr);
  else if (document_->shownBackWallPx())
    showRow(Room, false, tr("estimated: check that the back wall's corners sit on the room's corners"),
            tr("Accept the Box"), actions_.acceptBox);
  else if (preparing) showRow(Room, false, tr("being estimated…"), {}, nullptr);
  else
    showRow(Room, false, tr("not found: drag the back wall's corners onto the room's corners"), {},
            nullptr);
  // 2 Lights (outlined lights and sun shafts).
  const int lights = int(doc.lights.size() + doc.shafts.size());
  if (lights == 0)
    showRow(Lights, false, tr("none: objects are lit by gathered light only"), tr("Outline a Light"),
            photo ? actions_.outlineLight : nullptr);
  else showRow(Lights, true, tr("%n outlined", nullptr, lights), {}, nullptr);
  // 3 Objects.
  const int objects = document_->objectCount();
  if (objects == 0)
    showRow(Objects, false, tr("none yet (or drag one from the Library)"), tr("Insert Model…"),
            photo ? actions_.insertModel : nullptr);
  else showRow(Objects, true, tr("%n in the photo", nullptr, objects), {}, nullptr);
  // 4 Export.
  if (exportedPath_.isEmpty())
    showRow(Export, false, tr("not yet"), tr("Render Final Image…"),
            photo ? actions_.renderFinal : nullptr);
  else showRow(Export, true, tr("written to %1").arg(QFileInfo(exportedPath_).fileName()), {}, nullptr);

  const int current = currentStep();
  for (int i = 0; i < kStepCount; ++i) {
    Row& r = rows_[size_t(i)];
    QFont f = r.title->font();
    f.setBold(i == current);
    r.title->setFont(f);
    r.button->setDefault(i == current);
    // The number in a disc: the current step's highlighted, done ones green, later ones grey.
    const QString disc = i == current       ? QStringLiteral("palette(highlight)")
                         : done_[size_t(i)] ? QStringLiteral("#3a9a4a")
                                            : QStringLiteral("palette(mid)");
    r.number->setStyleSheet(
        QStringLiteral("QLabel { border-radius: 11px; color: white; background: %1; }").arg(disc));
    r.state->setEnabled(i <= current || done_[size_t(i)]);
  }
  if (fitter_) fitter_->fit();
  if (current == kStepCount && !announced_) {
    announced_ = true;
    Q_EMIT allDone();
  }
}

void StepsDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

void StepsDock::retranslate() {
  setWindowTitle(tr("Steps"));
  const QString titles[kStepCount] = {tr("Room"), tr("Lights"), tr("Objects"), tr("Export")};
  for (int i = 0; i < kStepCount; ++i) rows_[size_t(i)].title->setText(titles[i]);
  refresh();
}

}  // namespace inlay::studio
