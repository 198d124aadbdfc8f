// Insert Model…: what the studio makes of a model file before it becomes an object of the scene.
//
// loadModelForInsert() reads the file with the engine's readers (OBJ, PLY, glTF, GLB by our
// validating readers; FBX, COLLADA, 3DS through Assimp), under the studio's own limits, and
// decides the object's height:
//   - the model's own height when the file fixes its unit (glTF: metres; COLLADA: its <unit>;
//     FBX: its UnitScaleFactor) and that height is plausible (kMinPlausibleHeightM ..
//     kMaxPlausibleHeightM);
//   - otherwise the default height for new models (the Properties dock sets it), with a note
//     that says why (a unit the file does not state, or an absurd size such as 1 km or 1 µm).
// It touches no widget and no Document, so it runs on a worker thread (a large file must not
// freeze the window); the result goes back to the GUI thread by value.
#pragma once

#include "inlay/modeling/mesh.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

namespace inlay::studio {

// The studio's limits for an inserted model (the scene file itself allows more: a model larger
// than this can still be given by hand, and renders, only slowly).
struct ModelImportLimits {
  size_t maxTriangles = 5'000'000;
  size_t maxVertices = 15'000'000;
  long long maxFileBytes = 1'000'000'000LL;  // 1 GB
};

constexpr double kMinPlausibleHeightM = 0.01;  // a model that says it is smaller: absurd
constexpr double kMaxPlausibleHeightM = 20.0;  // one that says it is taller: absurd
constexpr double kDefaultModelHeightM = 0.75;  // a table, a chair's seat back, a floor vase

struct ModelImport {
  QString path;                              // absolute
  QString name;                              // the file's name without its extension
  std::shared_ptr<const TriangleMesh> mesh;  // as the engine will use it (file units)
  double heightM = kDefaultModelHeightM;     // the height the object gets
  bool ownSize = false;                      // heightM is the model's own (units known)
  QStringList notes;                         // what the user should know (status bar)
  size_t triangles = 0;
};

struct ModelLoadResult {
  std::optional<ModelImport> model;
  QString error;  // when !model: one line naming the file and the reason
};

// The file extensions the Insert Model dialog and drops accept (lower case, with the dot).
QStringList modelFileExtensions();
bool isModelFile(const QString& path);
// "Models (*.obj *.ply …);;All files (*)" in the current language.
QString modelFileFilter();

// Thread-safe; never throws. `defaultHeightM` is used when the model's own size is unknown or
// absurd.
ModelLoadResult loadModelForInsert(const QString& path, double defaultHeightM,
                                   const ModelImportLimits& limits = {});

// The height (file units) a mesh stands: its bounding box's y extent.
double meshHeightUnits(const TriangleMesh& mesh);

class ModelImportText {
  Q_DECLARE_TR_FUNCTIONS(inlay::studio::ModelImportText)
};

}  // namespace inlay::studio
