// The Steps dock: a guided start for a new user, four rows that each show the state of one step
// of a first composite and the one action that moves it on:
//   1 Room     the box: none yet, being estimated, estimated (Accept the Box), or yours;
//   2 Lights   how many are outlined; none: objects are lit by gathered light only (Outline a Light);
//   3 Objects  how many stand in the photo (Insert Model…; or a drag from the Library);
//   4 Export   not yet (Render Final Image…), or the file written.
// The first step not done is the current one (its title bold, its button the default); done
// steps show a check mark. Every state is read from the Document when it announces a change,
// plus the window's note that a composite was written (markExported). Once all four are done
// together the dock emits allDone() (the window hides it for good; View > Steps shows it
// again). Retranslates on QEvent::LanguageChange. GUI thread only.
#pragma once

#include <QDockWidget>
#include <QString>

#include <array>

class QAction;
class QLabel;
class QPushButton;

namespace inlay::studio {

class WrappedLabelFitter;

class Document;
struct ChangeEvent;

class StepsDock : public QDockWidget {
  Q_OBJECT

 public:
  enum Step { Room = 0, Lights, Objects, Export };
  static constexpr int kStepCount = 4;

  // The actions the steps' buttons trigger (their enabled state is followed).
  struct Actions {
    QAction* openPhoto = nullptr;
    QAction* acceptBox = nullptr;
    QAction* outlineLight = nullptr;
    QAction* insertModel = nullptr;
    QAction* renderFinal = nullptr;
  };

  StepsDock(Document* document, const Actions& actions, QWidget* parent = nullptr);

  bool isDone(Step step) const { return done_[size_t(step)]; }
  // The first step not done (kStepCount when all are).
  int currentStep() const;
  // What a step's row says now (for tests and the screenshot's reader).
  QString stateText(Step step) const;
  // The button of a step (hidden when the step is done or has nothing to do now).
  QPushButton* button(Step step) const { return rows_[size_t(step)].button; }

 public Q_SLOTS:
  // A composite of this document was written to `path` (Export, Render Final Image).
  void markExported(const QString& path);

 Q_SIGNALS:
  // Every step is done (emitted once per document, when the last one gets done).
  void allDone();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  struct Row {
    QLabel* number = nullptr;
    QLabel* title = nullptr;
    QLabel* state = nullptr;
    QPushButton* button = nullptr;
    QAction* action = nullptr;  // what the button triggers now (null: hidden)
  };
  void onDocumentChanged(const ChangeEvent& event);
  void refresh();
  void showRow(Step step, bool done, const QString& state, const QString& buttonText, QAction* action);
  void retranslate();

  Document* document_;
  Actions actions_;
  std::array<Row, kStepCount> rows_;
  std::array<bool, kStepCount> done_{};
  QString exportedPath_;
  WrappedLabelFitter* fitter_ = nullptr;  // the states' heights (see wrapped_labels.h)
  bool announced_ = false;                // allDone() was emitted for this document
};

}  // namespace inlay::studio
