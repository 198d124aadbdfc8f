#include "autosave.h"

#include "document.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSettings>
#include <QUndoStack>

#include <algorithm>

namespace inlay::studio {
namespace {

QString settingsFolder() {
  QString folder = QFileInfo(QSettings().fileName()).absolutePath();
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

QString filePrefix() {
  return settingsFolder() + QLatin1Char('/') + QCoreApplication::applicationName() +
         QStringLiteral("-recovery-");
}

// True when no living studio holds the lock at `lockPath` (it is stale or absent). A live
// studio's lock is never stale by age: it holds it for hours.
bool ownerIsGone(const QString& lockPath) {
  QLockFile probe(lockPath);
  probe.setStaleLockTime(0);
  if (probe.tryLock(0)) {
    probe.unlock();
    return true;
  }
  return probe.error() != QLockFile::LockFailedError;
}

}  // namespace

Autosaver::Autosaver(Document* document, QObject* parent) : QObject(parent), document_(document) {
  static int instances = 0;
  id_ = QStringLiteral("%1-%2").arg(QCoreApplication::applicationPid()).arg(instances++);
  lock_ = std::make_unique<QLockFile>(pathWith(".lock"));
  lock_->setStaleLockTime(0);
  if (!lock_->tryLock(0))  // a leftover of a dead process with our pid: QLockFile clears it
    error_ = tr("%1: cannot take the lock").arg(pathWith(".lock"));
  bool ok = false;
  int ms = qEnvironmentVariable("INLAY_AUTOSAVE_MS").toInt(&ok);
  if (!ok || ms <= 0)
    ms = 1000 * std::max(5, QSettings().value(QStringLiteral("autosaveSeconds"), 30).toInt());
  timer_.setInterval(ms);
  connect(&timer_, &QTimer::timeout, this, [this] { saveNow(); });
  connect(document_->undoStack(), &QUndoStack::indexChanged, this, [this] { dirty_ = true; });
  connect(document_->undoStack(), &QUndoStack::cleanChanged, this, [this](bool clean) {
    if (clean) discardOwn();
  });
  timer_.start();
}

Autosaver::~Autosaver() = default;

QString Autosaver::pathWith(const char* suffix) const {
  return filePrefix() + id_ + QLatin1String(suffix);
}

QString Autosaver::scenePath() const { return pathWith(".json"); }
QString Autosaver::infoPath() const { return pathWith(".info"); }

bool Autosaver::saveNow() {
  if (document_->undoStack()->isClean() || document_->scene().photo.empty()) {
    // Nothing unsaved (a freshly restored recovery is never clean, so it is kept).
    dirty_ = false;
    return true;
  }
  if (!dirty_) return true;
  const Status saved = saveSceneFile(QDir::toNativeSeparators(scenePath()).toStdString(),
                                     withAbsolutePaths(document_->scene()));
  if (!saved.ok()) {
    error_ = QString::fromStdString(saved.error().message());
    return false;
  }
  QJsonObject info;
  info[QStringLiteral("original")] = document_->filePath();
  info[QStringLiteral("saved")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
  QSaveFile file(infoPath());
  if (!file.open(QIODevice::WriteOnly) || file.write(QJsonDocument(info).toJson()) < 0 ||
      !file.commit()) {
    error_ = tr("%1: cannot write (%2)").arg(infoPath(), file.errorString());
    return false;
  }
  dirty_ = false;
  ++writes_;
  Q_EMIT autosaved();
  return true;
}

std::vector<Autosaver::Recovery> Autosaver::pendingAll() {
  std::vector<Recovery> out;
  const QString prefix = filePrefix();
  const QFileInfo prefixInfo(prefix);
  QDirIterator it(prefixInfo.absolutePath(), {prefixInfo.fileName() + QStringLiteral("*.json")},
                  QDir::Files);
  while (it.hasNext()) {
    Recovery r;
    r.scenePath = it.next();
    const QString stem = r.scenePath.chopped(int(qstrlen(".json")));
    if (!ownerIsGone(stem + QStringLiteral(".lock"))) continue;  // a running studio's work
    QFile file(stem + QStringLiteral(".info"));
    if (file.open(QIODevice::ReadOnly)) {
      const QJsonObject info = QJsonDocument::fromJson(file.readAll()).object();
      r.originalPath = info.value(QStringLiteral("original")).toString();
      r.saved = QDateTime::fromString(info.value(QStringLiteral("saved")).toString(), Qt::ISODate);
    }
    if (!r.saved.isValid()) r.saved = QFileInfo(r.scenePath).lastModified();
    out.push_back(r);
  }
  std::sort(out.begin(), out.end(),
            [](const Recovery& a, const Recovery& b) { return a.saved > b.saved; });
  return out;
}

std::optional<Autosaver::Recovery> Autosaver::pending() {
  std::vector<Recovery> all = pendingAll();
  if (all.empty()) return std::nullopt;
  return all.front();
}

void Autosaver::discard(const Recovery& recovery) {
  const QString stem = recovery.scenePath.chopped(int(qstrlen(".json")));
  QFile::remove(recovery.scenePath);
  QFile::remove(stem + QStringLiteral(".info"));
  QFile::remove(stem + QStringLiteral(".lock"));  // stale: its studio is gone
}

void Autosaver::discardAll() {
  for (const Recovery& r : pendingAll()) discard(r);
}

void Autosaver::discardOwn() {
  QFile::remove(scenePath());
  QFile::remove(infoPath());
}

}  // namespace inlay::studio
