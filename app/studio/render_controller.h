// Keeps a RenderSession in step with the Document and holds what the viewport shows: the
// newest composite and the photo (the "before" image).
//
// Threads: a RenderController lives on the GUI thread. It owns the RenderSession (whose render
// thread calls the CompositeSink) and reacts to Document::changed: a new prepared scene ->
// setScene, a moved object -> setObjectTransform (an instance update), a material or an
// inserted / deleted object -> setScene.
// Each call returns a new scene version; frames of older versions are dropped by the sink and
// again here. Images arrive by queued call; nothing here ever waits for the renderer.
// Destruction stops the session (joins its thread) before the sink is destroyed.
#pragma once

#include "document.h"
#include "frame_sink.h"

#include <QImage>
#include <QObject>

#include <memory>

namespace inlay::studio {

// What the viewport can show (the Layers dock). Each is a view of the document's prepared scene
// or of the newest render frame.
enum class Layer {
  Composite,       // the differential composite (the result)
  Photo,           // the photo alone (also the "before" view)
  Albedo,          // the reflectance the lighting stage decomposed the photo into
  DirectLight,     // the direct light of that decomposition
  WithObjects,     // the render of the room with the objects
  WithoutObjects,  // the render of the room alone
  Mask,            // where the objects cover the photo
  Difference,      // |composite - photo|, amplified 4x
};
constexpr int kLayerCount = 8;

class RenderController : public QObject {
  Q_OBJECT

 public:
  // A photo of more pixels than this gets its preview (the composite while editing) rendered at
  // a reduced size of about this many pixels, drawn scaled up to the photo's size; Render Final
  // Image renders at the photo's full size.
  static constexpr double kPreviewMaxPixels = 1.0e6;
  // The first preview wave after an edit samples blocks of this many pixels a side
  // (SessionOptions::startDivider; halving to full resolution).
  static constexpr int kFirstPreviewDivider = 16;
  // The preview's size for a photo of `width` x `height` (the photo's own up to kPreviewMaxPixels).
  static QSize previewSizeFor(int width, int height);

  explicit RenderController(Document* document, QObject* parent = nullptr);
  ~RenderController() override;

  // The newest composite of the current scene version (null until its first frame).
  const QImage& compositeImage() const { return composite_.srgb8; }
  // The size the preview renders at (the photo's own for photos up to kPreviewMaxPixels).
  QSize previewSize() const { return previewSize_; }
  // Its linear pixels (for export); null until the first frame.
  std::shared_ptr<const ImageF> compositeLinear() const { return composite_.linear; }
  // Statistics of compositeImage() (spp, error, seconds, version).
  const CompositeImage& frameInfo() const { return composite_; }
  bool hasFrame() const { return !composite_.srgb8.isNull(); }
  // The photo as the composite's background, 8-bit sRGB with the scene's exposure; a quick
  // preview decoded by Qt until the scene is prepared.
  const QImage& photoImage() const { return photo_; }
  // The scene version of the newest request to the renderer (0: none).
  quint64 requestedVersion() const { return requestedVersion_; }
  // True when the shown composite belongs to the newest request.
  bool isCurrent() const { return hasFrame() && composite_.sceneVersion >= requestedVersion_; }
  // The image of `layer` (8-bit sRGB, the photo's size), null when its source does not exist
  // yet (nothing prepared, or no frame). Converted on the GUI thread on first use and cached
  // until its source changes.
  QImage layerImage(Layer layer);
  // The denoised preview (View > Denoise Preview; render/denoise.h): every full-resolution frame
  // is denoised. Changing it restarts the current scene's render.
  void setDenoise(bool on);
  bool denoise() const { return denoise_; }
  // Paused: the preview renders nothing (Render Final Image has the processor); edits are still
  // taken and the preview starts again from the current scene when unpaused.
  void setPaused(bool paused);
  bool paused() const { return paused_; }
  // PathTracers the preview's session has made (RenderSession::tracerBuilds; 0 before the
  // first): a move makes none (tests).
  uint64_t tracerBuilds() const;

 Q_SIGNALS:
  // A new composite is in compositeImage(), or the images were cleared.
  void frameUpdated();

 private:
  void onDocumentChanged(const ChangeEvent& event);
  Q_INVOKABLE void takeFrame();  // by name from the render thread (see the constructor)
  void startScene();
  void request(uint64_t version);
  // Gives the session the preview scene of `prepared` (a new tracer) and requests its version.
  void requestScene(const PreparedScene& prepared);
  // The render scene of the preview: the shown objects, the camera scaled to previewSize_.
  RenderScene previewScene(const PreparedScene& prepared) const;

  Document* document_;
  CompositeImage composite_;
  QImage photo_;
  quint64 requestedVersion_ = 0;
  bool denoise_ = false;
  bool paused_ = false;
  QSize previewSize_;  // of the current prepared scene
  // Per object, whether the scene last given to the session left it out (hidden): a rename
  // (ObjectShown without a change of hidden) then restarts nothing.
  std::vector<bool> hiddenSent_;
  // layerImage()'s cache: per layer, the source it was made from.
  struct CachedLayer {
    const void* source = nullptr;
    QImage image;
  };
  CachedLayer layerCache_[kLayerCount];
  // Declared before session_: the session (and its thread) must go first.
  std::unique_ptr<CompositeSink> sink_;
  std::unique_ptr<RenderSession> session_;
};

}  // namespace inlay::studio
