#include "stage_text.h"
#include "engine_text.h"

#include <QCoreApplication>

#include <cstring>

namespace inlay::studio {
namespace {

constexpr const char* kContext = "inlay::studio::StageText";

// The stages (prepareScene's kStages in app/engine/src/pipeline.cpp) and the lighting's steps
// (StepTimer in lighting/src/estimate.cpp), as the engine names them. A name not listed here
// stays English.
const char* const kNames[] = {
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "photo"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "response"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "working copy"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "camera"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "layout"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "occluders"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "surfaces"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "room"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "lights"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "shafts"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "lighting"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "vignetting"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "sun ratio"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "refine"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "lighting refit"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "photo size"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "render scene"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "objects"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "grain"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "response check"),
    // The lighting's steps.
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "gather"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "light fit"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "unseen patches"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "retinex"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "decomposition"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "direct light"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "fit pixels"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "per-pixel albedo"),
    // The response check's step timing its two candidates together (pipeline.cpp, blockStep).
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "both candidates, side by side"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "both candidates, one after the other"),
    // ... and its step timing its two small copies together (pipeline.cpp, quickCheck).
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "both copies, side by side"),
    QT_TRANSLATE_NOOP("inlay::studio::StageText", "both copies, one after the other"),
};

// The response check's steps (app/engine/src/pipeline.cpp): the stages of its small copies and
// those it ran again with sRGB, each name after one of these prefixes.
struct Prefixed {
  const char* prefix;
  const char* text;
};
const Prefixed kPrefixed[] = {
    {"copy, curve: ", QT_TRANSLATE_NOOP("inlay::studio::StageText", "copy, curve: %1")},
    {"copy, sRGB: ", QT_TRANSLATE_NOOP("inlay::studio::StageText", "copy, sRGB: %1")},
    {"sRGB: ", QT_TRANSLATE_NOOP("inlay::studio::StageText", "sRGB: %1")},
};

QString nameOf(const std::string& name) {
  for (const Prefixed& p : kPrefixed)
    if (name.starts_with(p.prefix))
      return QCoreApplication::translate(kContext, p.text)
          .arg(nameOf(name.substr(std::strlen(p.prefix))));
  for (const char* n : kNames)
    if (name == n) return QCoreApplication::translate(kContext, n);
  return QString::fromStdString(name);
}

// "; CPU s: surfaces 0.05, gather 3.10" (empty without steps).
QString stepsText(const std::vector<StageStep>& steps) {
  QStringList shown;
  for (const StageStep& s : steps)
    shown << QStringLiteral("%1 %2").arg(nameOf(s.name)).arg(s.cpuSeconds, 0, 'f', 2);
  return shown.isEmpty() ? QString()
                         : QCoreApplication::translate("inlay::studio::StageText", "; CPU s: %1")
                               .arg(shown.join(QStringLiteral(", ")));
}

}  // namespace

QString stageLine(const StageRecord& stage) {
  const QString name = nameOf(stage.name);
  if (!stage.ran)
    return QCoreApplication::translate("inlay::studio::StageText", "%1: skipped, %2")
        .arg(name, engineStageText(QString::fromStdString(stage.reason)));
  QString line = QCoreApplication::translate("inlay::studio::StageText", "%1: %2 s, CPU %3 s")
                     .arg(name)
                     .arg(stage.seconds, 0, 'f', 3)
                     .arg(stage.cpuSeconds, 0, 'f', 3);
  if (!stage.detail.empty())
    line += QStringLiteral(" (%1)").arg(engineStageText(QString::fromStdString(stage.detail)));
  if (stage.reducedImage)
    line += QLatin1Char(' ') + QCoreApplication::translate("inlay::studio::StageText", "at %1 x %2 px")
                                   .arg(stage.workingWidth)
                                   .arg(stage.workingHeight);
  return line + stepsText(stage.steps);
}

QStringList stageNames() {
  QStringList out;
  for (const char* n : kNames) out << QString::fromUtf8(n);
  for (const Prefixed& p : kPrefixed) out << QString::fromUtf8(p.text);
  return out;
}

}  // namespace inlay::studio
