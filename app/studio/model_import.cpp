#include "model_import.h"

#include <QFileInfo>
#include <QLocale>

#include <cmath>

namespace inlay::studio {
namespace {

QString heightText(double metres) {
  if (metres >= 1000) return ModelImportText::tr("%1 km").arg(metres / 1000, 0, 'g', 3);
  if (metres >= 1) return ModelImportText::tr("%1 m").arg(metres, 0, 'f', 2);
  if (metres >= 0.01) return ModelImportText::tr("%1 cm").arg(metres * 100, 0, 'f', 1);
  if (metres >= 1e-5) return ModelImportText::tr("%1 mm").arg(metres * 1000, 0, 'g', 3);
  return ModelImportText::tr("%1 µm").arg(metres * 1e6, 0, 'g', 3);
}

QString formatName(const std::string& format) {
  if (format == "gltf") return QStringLiteral("glTF");
  if (format == "dae") return QStringLiteral("COLLADA");
  return QString::fromStdString(format).toUpper();
}

// The object's height from the file's unit, or the default with the reason.
void chooseHeight(ModelImport& m, const MeshFileInfo& info, double defaultHeightM) {
  const double units = meshHeightUnits(*m.mesh);
  m.heightM = defaultHeightM;
  const QString height = heightText(defaultHeightM);
  if (!(info.metresPerUnit > 0)) {
    m.notes << ModelImportText::tr(
                   "%1 files do not state their unit: %2 was scaled to %3 high "
                   "(change Height in Properties).")
                   .arg(formatName(info.format), m.name, height);
    return;
  }
  const double own = units * info.metresPerUnit;
  if (own >= kMinPlausibleHeightM && own <= kMaxPlausibleHeightM && std::isfinite(own)) {
    m.heightM = own;
    m.ownSize = true;
    return;
  }
  m.notes << ModelImportText::tr(
                 "%1 says it is %2 high, an absurd size: it was inserted "
                 "%3 high instead (change Height in Properties).")
                 .arg(m.name, heightText(own), height);
}

}  // namespace

QStringList modelFileExtensions() {
  QStringList out;
  for (const std::string& e : meshFileExtensions()) out << QString::fromStdString(e);
  return out;
}

bool isModelFile(const QString& path) {
  const QString suffix = QStringLiteral(".") + QFileInfo(path).suffix().toLower();
  return modelFileExtensions().contains(suffix);
}

QString modelFileFilter() {
  QStringList globs;
  for (const QString& e : modelFileExtensions()) globs << QStringLiteral("*") + e;
  return ModelImportText::tr("3D models (%1)").arg(globs.join(QLatin1Char(' '))) + QStringLiteral(";;") +
         ModelImportText::tr("All files (*)");
}

double meshHeightUnits(const TriangleMesh& mesh) {
  const Eigen::AlignedBox3f b = mesh.bounds();
  return b.isEmpty() ? 0.0 : double(b.max().y() - b.min().y());
}

ModelLoadResult loadModelForInsert(const QString& path, double defaultHeightM,
                                   const ModelImportLimits& limits) {
  ModelLoadResult out;
  const QFileInfo file(path);
  const QString shown = file.fileName();
  if (!isModelFile(path)) {
    out.error = ModelImportText::tr("%1: not a model file Inlay reads (%2).")
                    .arg(shown, modelFileExtensions().join(QStringLiteral(", ")));
    return out;
  }
  MeshLimits meshLimits;
  meshLimits.maxTriangles = limits.maxTriangles;
  meshLimits.maxVertices = limits.maxVertices;
  meshLimits.maxFileBytes = limits.maxFileBytes;
  MeshFileInfo info;
  Expected<TriangleMesh> mesh = [&]() -> Expected<TriangleMesh> {
    try {
      return loadMesh(file.absoluteFilePath().toStdString(), meshLimits, &info);
    } catch (const std::exception& e) {  // loadMesh reports its own; this is a last guard
      return Error{file.absoluteFilePath().toStdString(), "", e.what()};
    }
  }();
  if (!mesh.ok()) {
    const Error& e = mesh.error();
    out.error = ModelImportText::tr("%1: %2").arg(
        shown, QString::fromStdString(e.key.empty() ? e.reason : e.key + ": " + e.reason));
    if (e.reason.find("exceed") != std::string::npos || e.reason.find("more than") != std::string::npos)
      out.error += QLatin1Char(' ') +
                   ModelImportText::tr("(Inlay inserts models of up to %1 triangles.)")
                       .arg(QLocale().toString(qulonglong(limits.maxTriangles)));
    return out;
  }
  if (!(meshHeightUnits(*mesh) > 0)) {
    out.error = ModelImportText::tr(
                    "%1: the model is flat (it has no height), so it cannot stand "
                    "in the room.")
                    .arg(shown);
    return out;
  }
  ModelImport m;
  m.path = file.absoluteFilePath();
  m.name = file.completeBaseName();
  m.triangles = mesh->triangles.size();
  if (mesh->normals.empty())
    m.notes << ModelImportText::tr("%1 has no normals: it is shaded flat.").arg(shown);
  m.mesh = std::make_shared<const TriangleMesh>(std::move(mesh.value()));
  chooseHeight(m, info, defaultHeightM);
  out.model = std::move(m);
  return out;
}

}  // namespace inlay::studio
