// Render Final Image: the composite of the scene as it is when started, at the photo's full
// resolution, rendered to the scene's noise target (render.noise, adaptive sampling; render.spp
// samples per pixel at most, render.seconds when set), as `inlay-cli render` does, then written
// to a file (PNG, JPEG, TIFF through the photo's camera response, or linear EXR) atomically: a
// cancelled or failed render never leaves a half-written file, nor replaces the user's old one.
//
// Threads: a FinalRender lives on the GUI thread. Its RenderSession renders on its own thread
// (the interactive preview's session is paused meanwhile by the caller); frames are handed over
// by queued call. The composite of the final frame and the file's encoding run on a worker
// thread, so the window stays responsive. cancel() stops either; the destructor joins both.
#pragma once

#include "inlay/engine/pipeline.h"

#include <QImage>
#include <QObject>
#include <QString>

#include <memory>

class QThread;

namespace inlay::studio {

class FinalRender : public QObject {
  Q_OBJECT

 public:
  struct Progress {
    double fraction = 0;  // 0..1, never decreasing
    int spp = 0;          // most samples any pixel has
    double meanSpp = 0;
    double estimatedError = 0;
    double noiseTarget = 0;
    double seconds = 0;
  };

  // Starts rendering `scene` (copied: later edits do not reach it) for `path`; `maxSpp` > 0
  // caps the samples per pixel below render.spp (tests, quick drafts).
  FinalRender(const PreparedScene& scene, const QString& path, int maxSpp = 0,
              QObject* parent = nullptr);
  ~FinalRender() override;

  QString path() const { return path_; }
  bool running() const { return !finished_; }
  bool cancelled() const { return cancelled_; }
  const Progress& progress() const { return progress_; }
  // The image written (linear, as composited); null until finished.
  std::shared_ptr<const ImageF> composite() const { return composite_; }
  // The same for the screen: 8-bit through the photo's camera response (the codes an 8-bit
  // file holds; sRGB for a linear photo); null until finished.
  const QImage& shownImage() const { return shown_; }
  // The session options the render uses (for the docs and tests).
  static SessionOptions optionsFor(const PreparedScene& scene, int maxSpp = 0);

 public Q_SLOTS:
  // Stops rendering (or, once saving began, lets the save finish); finished(false, ...) follows.
  void cancel();

 Q_SIGNALS:
  void progressed(const inlay::studio::FinalRender::Progress& progress);
  // ok: the file was written; message: one line for the status bar (what was written, or why
  // nothing was).
  void finished(bool ok, const QString& message);

 private:
  class Sink;
  Q_INVOKABLE void takeFrame();
  void startSaving(const std::shared_ptr<const RenderFrame>& frame);
  void finish(bool ok, const QString& message);

  QString path_;
  std::shared_ptr<const PreparedScene> context_;  // what compositeOf reads
  SessionOptions options_;
  Progress progress_;
  bool cancelled_ = false;
  bool finished_ = false;
  std::shared_ptr<const ImageF> composite_;
  QImage shown_;
  QThread* saver_ = nullptr;
  // Declared last: destroyed first (joins the render thread before the sink goes).
  std::unique_ptr<Sink> sink_;
  std::unique_ptr<RenderSession> session_;
};

}  // namespace inlay::studio

Q_DECLARE_METATYPE(inlay::studio::FinalRender::Progress)
