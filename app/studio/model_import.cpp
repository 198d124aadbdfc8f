#include "model_import.h"
#include "engine_text.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QRegularExpression>

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

// The JSON of a .gltf file or of a .glb's first chunk (empty when it is not readable).
QJsonObject gltfJson(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  QByteArray bytes = f.read(64 << 20);
  if (bytes.startsWith("glTF")) {  // binary: a 12-byte header, then the JSON chunk
    if (bytes.size() < 20) return {};
    const quint32 length = quint32(uchar(bytes[12])) | quint32(uchar(bytes[13])) << 8 |
                           quint32(uchar(bytes[14])) << 16 | quint32(uchar(bytes[15])) << 24;
    bytes = bytes.mid(20, int(std::min<quint32>(length, quint32(bytes.size() - 20))));
  }
  return QJsonDocument::fromJson(bytes).object();
}

// Image textures the model names: Inlay renders its materials' own values, never the images,
// so the user is told (and told which named files are missing altogether).
QStringList textureNotes(const QString& path, const QString& shown) {
  const QFileInfo file(path);
  const QString suffix = file.suffix().toLower();
  QStringList missing;
  int images = 0;  // named images that are there (or embedded)
  auto note = [&](const QString& image) {
    if (image.startsWith(QLatin1String("data:")) || file.dir().exists(image)) ++images;
    else missing << image;
  };
  if (suffix == QLatin1String("gltf") || suffix == QLatin1String("glb")) {
    const QJsonObject json = gltfJson(path);
    for (const auto& image : json.value(QLatin1String("images")).toArray()) {
      const QString uri = image.toObject().value(QLatin1String("uri")).toString();
      if (!uri.isEmpty()) note(uri);
      else ++images;  // in a buffer of the file
    }
  } else if (suffix == QLatin1String("obj")) {
    QFile obj(path);
    if (!obj.open(QIODevice::ReadOnly | QIODevice::Text)) return {};
    for (int n = 0; n < 100000 && !obj.atEnd(); ++n) {
      const QString line = QString::fromUtf8(obj.readLine()).trimmed();
      if (!line.startsWith(QLatin1String("mtllib "))) continue;
      const QString mtl = line.mid(7).trimmed();
      QFile lib(file.dir().filePath(mtl));
      if (!lib.open(QIODevice::ReadOnly | QIODevice::Text)) {
        missing << mtl;
        continue;
      }
      static const QRegularExpression map(
          QStringLiteral("^\\s*(map_\\w+|bump|disp)\\s+(?:-\\S+\\s+\\S+\\s+)*(\\S.*)$"));
      for (const QString& l : QString::fromUtf8(lib.read(8 << 20)).split(QLatin1Char('\n')))
        if (const QRegularExpressionMatch m = map.match(l.trimmed()); m.hasMatch())
          note(m.captured(2).trimmed());
    }
  }
  QStringList notes;
  if (!missing.isEmpty())
    notes << ModelImportText::tr(
                 "%1 names files that are not beside it (%2): its materials' own "
                 "colours are used, or a grey default.")
                 .arg(shown, missing.join(QStringLiteral(", ")));
  if (images > 0)
    notes << ModelImportText::tr(
                 "%1's image textures are not rendered: Inlay uses its materials' "
                 "base colour, metallic and roughness values.")
                 .arg(shown);
  return notes;
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
        shown, engineText(QString::fromStdString(e.key.empty() ? e.reason : e.key + ": " + e.reason)));
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
  m.notes << textureNotes(m.path, shown);
  m.mesh = std::make_shared<const TriangleMesh>(std::move(mesh.value()));
  chooseHeight(m, info, defaultHeightM);
  out.model = std::move(m);
  return out;
}

}  // namespace inlay::studio
