// The log dock: after each preparation of the scene, what it did, stage by stage (each stage's
// seconds, or why this scene skipped it: "shafts: skipped, no sun marked"), and its warnings;
// or why it failed. Newest at the bottom; the same lines as `inlay-cli --verbose`, in the
// studio's language (stage_text.h). GUI thread only.
#pragma once

#include "document.h"

#include <QDockWidget>

class QPlainTextEdit;

namespace inlay::studio {

class LogDock : public QDockWidget {
  Q_OBJECT
 public:
  explicit LogDock(Document* document, QWidget* parent = nullptr);
  // All the log's lines.
  QString text() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void onDocumentChanged(const ChangeEvent& event);
  void retranslate();

  Document* document_;
  QPlainTextEdit* log_;
};

}  // namespace inlay::studio
