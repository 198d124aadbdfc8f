#include "autosave.h"

#include "document.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSettings>
#include <QUndoStack>

namespace inlay::studio {
namespace {

QString settingsFolder() {
  const QString folder = QFileInfo(QSettings().fileName()).absolutePath();
  QDir().mkpath(folder);
  return folder;
}

// The scene with every path absolute: the recovery file lives elsewhere than the scene did.
SceneDoc withAbsolutePaths(SceneDoc doc) {
  if (!doc.photoResolved.empty()) doc.photo = doc.photoResolved;
  for (ObjectKeys& o : doc.objects)
    if (!o.meshResolved.empty()) o.mesh = o.meshResolved;
  return doc;
}

}  // namespace

Autosaver::Autosaver(Document* document, QObject* parent) : QObject(parent), document_(document) {
  bool ok = false;
  int ms = qEnvironmentVariable("INLAY_AUTOSAVE_MS").toInt(&ok);
  if (!ok || ms <= 0) ms = 1000 * std::max(5, QSettings().value(QStringLiteral("autosaveSeconds"), 30).toInt());
  timer_.setInterval(ms);
  connect(&timer_, &QTimer::timeout, this, [this] { saveNow(); });
  connect(document_->undoStack(), &QUndoStack::indexChanged, this, [this] { dirty_ = true; });
  connect(document_->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
    if (clean) discard();
  });
  timer_.start();
}

QString Autosaver::recoveryScenePath() {
  return settingsFolder() + QLatin1Char('/') + QCoreApplication::applicationName() +
         QStringLiteral("-recovery.json");
}

QString Autosaver::recoveryInfoPath() {
  return settingsFolder() + QLatin1Char('/') + QCoreApplication::applicationName() +
         QStringLiteral("-recovery.info");
}

bool Autosaver::saveNow() {
  if (document_->undoStack()->isClean() || document_->scene().photo.empty()) {
    // Nothing unsaved (a freshly restored recovery is never clean, so it is kept).
    dirty_ = false;
    return true;
  }
  if (!dirty_) return true;
  const Status saved =
      saveSceneFile(QDir::toNativeSeparators(recoveryScenePath()).toStdString(),
                    withAbsolutePaths(document_->scene()));
  if (!saved.ok()) {
    error_ = QString::fromStdString(saved.error().message());
    return false;
  }
  QJsonObject info;
  info[QStringLiteral("original")] = document_->filePath();
  info[QStringLiteral("saved")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
  QSaveFile file(recoveryInfoPath());
  if (!file.open(QIODevice::WriteOnly) ||
      file.write(QJsonDocument(info).toJson()) < 0 || !file.commit()) {
    error_ = tr("%1: cannot write (%2)").arg(recoveryInfoPath(), file.errorString());
    return false;
  }
  dirty_ = false;
  ++writes_;
  Q_EMIT autosaved();
  return true;
}

std::optional<Autosaver::Recovery> Autosaver::pending() {
  Recovery r;
  r.scenePath = recoveryScenePath();
  if (!QFile::exists(r.scenePath)) return std::nullopt;
  QFile file(recoveryInfoPath());
  if (file.open(QIODevice::ReadOnly)) {
    const QJsonObject info = QJsonDocument::fromJson(file.readAll()).object();
    r.originalPath = info.value(QStringLiteral("original")).toString();
    r.saved = QDateTime::fromString(info.value(QStringLiteral("saved")).toString(), Qt::ISODate);
  }
  if (!r.saved.isValid()) r.saved = QFileInfo(r.scenePath).lastModified();
  return r;
}

void Autosaver::discard() {
  QFile::remove(recoveryScenePath());
  QFile::remove(recoveryInfoPath());
}

}  // namespace inlay::studio
