// A scene's pixel keys for its photo enlarged `k` times (shared by the big-photo tests).
#pragma once

#include "inlay/modeling/scene_file.h"

namespace inlay::test {

inline void scalePixelKeys(SceneDoc& doc, double k) {
  if (doc.camera.focalPx) *doc.camera.focalPx *= k;
  if (doc.camera.principalPx) *doc.camera.principalPx *= k;
  if (doc.camera.vanishingPointsPx)
    for (Vec2& v : *doc.camera.vanishingPointsPx) v *= k;
  if (doc.layout.backWallPx)
    for (Vec2& v : *doc.layout.backWallPx) v *= k;
  for (LightKeys& l : doc.lights)
    for (Vec2& v : l.pointsPx) v *= k;
  for (ObjectKeys& o : doc.objects) o.basePx *= k;
}

}  // namespace inlay::test
