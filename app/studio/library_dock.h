// The Library dock: the pieces of the model library that ships with Inlay (resources/models,
// share/inlay/models when installed; engine/model_library.h), each as its thumbnail (rendered
// into the example by Inlay's own path tracer) with its translated title; a tooltip gives its
// size. Dragging a thumbnail starts a drag whose QMimeData holds the piece's .glb as a file URL
// (text/uri-list), so any drop target that takes model files (the viewport) takes a piece;
// double-clicking one emits pieceActivated with the same file.
// GUI thread only.
#pragma once

#include <QDockWidget>
#include <QListWidget>

class QLabel;

namespace inlay::studio {

// The list: icon mode, drag only; its drags carry the pieces' files as URLs.
class LibraryList : public QListWidget {
  Q_OBJECT

 public:
  using QListWidget::QListWidget;

  // Public (QListWidget has them protected) so that tests and other drag sources can ask.
  QStringList mimeTypes() const override;
  QMimeData* mimeData(const QList<QListWidgetItem*>& items) const override;
};

class LibraryDock : public QDockWidget {
  Q_OBJECT

 public:
  // Reads the library from `modelsDir` (empty: inlay::modelLibraryDir()).
  explicit LibraryDock(QWidget* parent = nullptr, const QString& modelsDir = {});
  LibraryList* list() const { return list_; }

  // The English titles of the bundled pieces, marked for translation (context "LibraryDock").
  static QString translatedTitle(const QString& englishTitle);

 Q_SIGNALS:
  void pieceActivated(const QString& glbPath);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void load();
  void retranslate();

  QString modelsDir_;
  QString problem_;       // why the library could not be read (the reader's own words)
  bool missing_ = false;  // no library folder was found
  LibraryList* list_;
  QLabel* message_;
};

}  // namespace inlay::studio
