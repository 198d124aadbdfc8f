// Word-wrapped labels in a dock: a QDockWidget does not pass height-for-width on to its widget,
// and QLabel::heightForWidth never answers less than the label's minimum height, so a wrapped
// label either has its last lines cut off or keeps a gap once its text gets shorter. A
// WrappedLabelFitter watches the dock's widget (its resizes and layout requests) and sets each
// of its labels' minimum height to what the label's text takes wrapped at the label's width.
// Their width is the layout's (horizontal size policy Ignored): a long text never widens the
// dock. GUI thread only.
#pragma once

#include <QList>
#include <QObject>
#include <QPointer>

class QLabel;
class QWidget;

namespace inlay::studio {

class WrappedLabelFitter : public QObject {
 public:
  // `container`: the widget whose width decides the labels' (it is also the parent).
  WrappedLabelFitter(QWidget* container, const QList<QLabel*>& labels);
  // Now (after a change of text); resizes and layout changes fit on their own.
  void fit();
  // The height `label`'s text takes wrapped at the label's width, margins included.
  static int neededHeight(const QLabel* label);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  QWidget* container_;
  QList<QPointer<QLabel>> labels_;
  bool queued_ = false;
};

}  // namespace inlay::studio
