// The main window's status bar: transient messages readable at any window width, in any
// language.
//
// QStatusBar draws a temporary message on one line left of its permanent fields and cuts it off
// where the first field begins, so a long message (a model's notes, the final render's progress,
// German and French above all) lost its end. Here the message is a StatusMessage: it wraps onto
// a second line when one is not enough and only beyond kMaxLines ends with "…", the whole text
// then in its tooltip. The bar is always kMaxLines high, so a message never moves the viewport
// (a bar that grew with its message resized the photo under the user's cursor). The fields (samples, rate, error, time,
// zoom) keep widths that do not follow every new figure, and in a narrow window the least
// important ones make way so the message keeps at least kMinMessageWidth pixels.
//
// showMessage(), clearMessage() and currentMessage() are QStatusBar's own: callers and tests go
// on using them; the bar only draws the message differently. GUI thread only.
#pragma once

#include <QStatusBar>
#include <QStringList>
#include <QWidget>

#include <vector>

class QLabel;

namespace inlay::studio {

// A message of up to kMaxLines word-wrapped lines, the last one elided when the text needs more.
class StatusMessage : public QWidget {
  Q_OBJECT

 public:
  static constexpr int kMaxLines = 2;

  explicit StatusMessage(QWidget* parent = nullptr);
  void setText(const QString& text);
  QString text() const { return text_; }
  // The lines as drawn (at most kMaxLines; the last one ends with "…" when elided()).
  QStringList shownLines() const { return lines_; }
  bool elided() const { return elided_; }
  // What hovering shows: the whole message when it is elided (and the bar's own tooltip, when
  // set, below it); empty otherwise (the bar's tooltip shows).
  QString toolTipText() const;
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 protected:
  bool event(QEvent* event) override;
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void relayout();
  int linesHeight() const;

  QString text_;
  QStringList lines_;
  bool elided_ = false;
};

class StatusBar : public QStatusBar {
  Q_OBJECT

 public:
  // The width the message keeps before fields are hidden (unless the bar itself is narrower).
  static constexpr int kMinMessageWidth = 320;

  explicit StatusBar(QWidget* parent = nullptr);
  // Adds a permanent field right of the earlier ones. In a narrow bar, fields of a lower
  // `priority` are hidden first (0: never hidden).
  void addField(QLabel* field, int priority);
  // The texts a field may show (in the current language): its width fits the widest, so the
  // message does not re-wrap at every new figure. Call again after a change of language.
  void setFieldSamples(QLabel* field, const QStringList& samples);
  StatusMessage* message() const { return message_; }

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  struct Field {
    QLabel* label;
    int priority;
  };
  void fitFields();

  StatusMessage* message_;
  std::vector<Field> fields_;
  bool fitting_ = false;
};

}  // namespace inlay::studio
