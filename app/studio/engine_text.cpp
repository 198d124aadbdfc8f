#include "engine_text.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <optional>
#include <vector>

namespace inlay::studio {
namespace {

constexpr const char* kContext = "inlay::studio::EngineText";

// The engine's sentences a studio user meets, exactly as the engine writes them, with %1, %2,
// ... (in order) where it puts a number, a key, a name or a nested reason. Keep in step with
// the engine's strings (modeling/src/io/mesh.cpp, app/engine/src/pipeline.cpp,
// lighting/src/estimate.cpp, refine.cpp and decompose.cpp, modeling/src/camera/response.cpp and
// noise_level.cpp): a sentence changed there stays English here.
// A fitted curve as CameraResponse::describe() gives it: inside a warning's sentence and inside
// the response check's stage line alike.
const char* const kCurveText =
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "toe_shoulder (power %1, toe %2, shoulder %3)");

const char* const kSentences[] = {
    // The camera estimate's (modeling/src/camera/estimate_camera.cpp), drawn on the photo.
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "vanishing point %1: only %2 supporting line(s); it rests on the other two"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "vanishing point %1: its lines are nearly parallel in the photo, so its "
                      "distance is uncertain"),
    // Model files refused by the readers (the studio adds the file name).
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "empty file"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "cannot open for reading"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "read failed"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "no triangles"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "import failed: %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "non-finite coordinate '%1'"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "non-finite coordinate"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "malformed number '%1'"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "malformed face index '%1'"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "face corner without a vertex index"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "face index 0 (OBJ indices start at 1)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "a face needs at least 3 vertices"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "more than %1 triangles"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "more than %1 vertices"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 vertices exceed the limit of %2"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "'%1' needs %2 numbers"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "not a PLY file (missing 'ply' magic)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "not a GLB file"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "invalid glTF JSON"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "buffer file not found: %1"),
    // The preparation's warnings.
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "none given; the objects are lit by the room's gathered light only"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "ignored, the photo is already linear (EXR/HDR)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the estimated back wall is unusable (%1); using a 5 x 5.5 m room: give "
                      "layout.back_wall_px"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the photo shows no clear room structure; the camera is a fallback (prior "
                      "focal length, upright): give camera.vanishing_points_px for a reliable "
                      "result"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the photo shows no clear room structure; the camera is a fallback (default "
                      "focal length, upright): give camera.vanishing_points_px for a reliable "
                      "result"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "strength kept as estimated: %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the window the sun comes through is out of view; its sky is a light of %1 x "
                      "%2 m on the %3 (where the beam came from), its intensity fitted (give "
                      "source_box_px, or outline the window as a light, to choose)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "%1's matte shows the floor under the top at %2 of %3 points, so it is a "
                      "slab %4 m thick (give thickness_m to choose; 0: solid)"),
    // The lighting's notes.
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "gathered light still changed by %1% in the last of %2 passes (the walls the "
                      "camera does not see are uncertain)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "lights %1 are out of view: they share one radiance (the photo shows only "
                      "their sum)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the ceiling the camera does not see: the light fit's model of the room gives "
                      "it %1 grey, not the seen walls' mean (%2; a sunlit patch lights the ceiling "
                      "straight on, and the photo does not show its albedo)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "outside the room; moved %1 m to fit inside it"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "larger than the room in every direction; its position is kept"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "%1 lights none of the room the photo shows: its intensity stays at its start"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the photo's direct light is black: the lights are fitted to darkness"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "light refinement failed (%1): the start is kept"),
    // The decomposition's report when it stops early (lighting/src/decompose.cpp; a lighting
    // note under the head "decomposition").
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "not converged: stopped by %1 after %2 iterations (%3 s): primal residual %4, "
                      "dual %5, tolerance %6"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the iteration cap"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "non-finite residuals"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "cancellation"),
    // The camera response estimate's decisions and warnings (modeling/src/camera/response.cpp
    // and noise_level.cpp; the Camera Response dock's details). studio_translation_test forces
    // each of them out of the estimate and fails on one that stays English.
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "noise level"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "edge"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the fitted %1 lowers the %2 residual only from %3 to %4"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the %1 residual of sRGB, %2, is within what photos read rightly as sRGB "
                      "show (below %3), so the fitted %4 is not trusted"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the fitted %1 spans %2 stops between codes 128 and 254 (sRGB 2.2, at most "
                      "%3 trusted), but the photo's noise was measured at only %4 code level in "
                      "that half (%5 needed), so the shoulder is an extrapolation"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the fitted %1 spans %2 stops between codes 128 and 254 (sRGB 2.2, at most "
                      "%3 trusted), but the photo's noise was measured at only %4 code levels in "
                      "that half (%5 needed), so the shoulder is an extrapolation"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "too little evidence for a curve other than sRGB (%1)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "an implausible curve was refused (%1); using sRGB"),
    // The pipeline's check of an estimated curve (app/engine/src/pipeline.cpp).
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the light fit's residual with the fitted %1 is %2, with sRGB %3"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the estimated curve was not used (%1); using sRGB"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the fitted %1 lies at the family's bound (%2): the camera's curve may be "
                      "stronger than the family holds"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1; using sRGB (give camera.response to choose)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the photo is empty"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "most of the photo is clipped to black or white"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the photo is nearly one flat colour"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the photo is nearly binary (%1 grey levels in use)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "too few clean edges between flat regions (%1 of %2 needed)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the edges cover only codes %1 to %2"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "cancelled"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "too few flat regions to measure the noise (%1 flat 8 x 8 blocks)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the flat regions cover too few codes to measure the noise against them"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the photo shows no measurable noise"),
    // A fitted curve inside the sentences above.
    kCurveText,
};

// The preparation's stage lines (app/engine/src/pipeline.cpp: the reasons a scene skips a
// stage, and the parts of what a stage did, which describeStage() joins with ", "). Matched by
// engineStageText() only, never among the messages above: a short template such as "%1 lights"
// would take a message's ending for its own.
const char* const kStageTexts[] = {
    // Why a stage was skipped.
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "none marked"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "no sun marked"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "none inserted"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "the lights are kept as estimated (initial lights asked for)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "turned off"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "no light marked"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "every light locked or given (\"refine\": false)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "every light locked"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the working copy is the photo"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the lights were not refined"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "no light moved"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "lights moved by at most %1 % of their size (under %2 %): the first "
                      "estimate's lights are kept"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "camera.vignetting is \"none\" (the default)"),
    // What a stage did, part by part.
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 x %2 px"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "linear photo"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "estimated"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the photo area-averaged"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the photo's own size"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "estimated from the photo"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the file's vanishing points and back wall"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "estimated from the photo once, for the response check's copy"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 x %2 m"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 m high"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 matte"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 mattes"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "v %1 applied"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the light fit's residual shows %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the light fit run again"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 surface built"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 surfaces built"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 surface"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 surfaces"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 reflective"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 outlined"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 placed in 3D"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 sun"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 suns"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 sky through an unseen window"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 skies through unseen windows"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 light"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 lights"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 pass"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 passes"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the first estimate's rays replayed"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 points x %2 rays"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 light fit iterations"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 of %2 light refined"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 of %2 lights refined"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 evaluation"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 evaluations"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "lights moved by at most %1 % of their size; the first estimate fits the "
                      "photo better (log residual %2 against %3) and is kept; the refit took %4"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText",
                      "lights moved by at most %1 % of their size; the refit is kept (log residual "
                      "%2 against the first estimate's %3)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "from %1 x %2 px: maps %3 s"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "surfaces cast %1 s"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 object"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "%1 objects"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "none"),
    // The response check's verdict (pipeline.cpp, checkRecord): both light fits' residuals, then
    // the small copies' comparison.
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the curve kept: %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "sRGB kept: %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "the light fit's residual with the fitted %1 is %2"),
    kCurveText,
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "with sRGB %1; on %2 x %3 copies %4 against %5"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "with sRGB %1; no quick comparison"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "log ratio %1 beyond %2"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "log ratio %1 within %2"),
};

// Heads of "HEAD: REST" that are words rather than keys: translated, then the rest.
const char* const kHeads[] = {
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "line %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "header line %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "vertex %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "face %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "sun %1"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "lights"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "estimate"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "lighting"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "lighting (refit)"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "light refinement"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "decomposition"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "layout"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "camera response"),
    QT_TRANSLATE_NOOP("inlay::studio::EngineText", "kept sRGB"),
};

struct Pattern {
  const char* source;
  QRegularExpression re;
};

// "more than %1 triangles" -> ^more than (.+?) triangles$
QRegularExpression patternOf(const QString& source) {
  static const QRegularExpression placeholder(QStringLiteral("%\\d"));
  QString re = QStringLiteral("^");
  qsizetype at = 0;
  for (auto it = placeholder.globalMatch(source); it.hasNext();) {
    const QRegularExpressionMatch m = it.next();
    re += QRegularExpression::escape(source.mid(at, m.capturedStart() - at)) + QStringLiteral("(.+?)");
    at = m.capturedEnd();
  }
  re += QRegularExpression::escape(source.mid(at)) + QStringLiteral("$");
  return QRegularExpression(re, QRegularExpression::DotMatchesEverythingOption);
}

template <size_t N>
std::vector<Pattern> patternsOf(const char* const (&sources)[N]) {
  std::vector<Pattern> out;
  for (const char* s : sources) out.push_back({s, patternOf(QString::fromUtf8(s))});
  return out;
}

// `text` translated when one of `patterns` matches it whole; its parts translated in turn by
// `part`.
std::optional<QString> translateWhole(const QString& text, const std::vector<Pattern>& patterns,
                                      QString (*part)(const QString&) = engineText) {
  for (const Pattern& p : patterns) {
    const QRegularExpressionMatch m = p.re.match(text);
    if (!m.hasMatch()) continue;
    QString out = QCoreApplication::translate(kContext, p.source);
    for (int i = 1; i <= m.lastCapturedIndex(); ++i) out = out.arg(part(m.captured(i)));
    return out;
  }
  return std::nullopt;
}

// A head the engine puts before ": ": a file or a scene key ("objects[1].mesh", no spaces).
bool isKeyOrFile(const QString& head) {
  return !head.isEmpty() && (!head.contains(QLatin1Char(' ')) || head.contains(QLatin1Char('/')));
}

}  // namespace

QString engineText(const QString& english) {
  static const std::vector<Pattern> sentences = patternsOf(kSentences);
  static const std::vector<Pattern> heads = patternsOf(kHeads);
  if (std::optional<QString> whole = translateWhole(english, sentences)) return *whole;
  const qsizetype colon = english.indexOf(QStringLiteral(": "));
  if (colon <= 0) return english;
  const QString head = english.left(colon);
  const QString rest = english.mid(colon + 2);
  std::optional<QString> shownHead = translateWhole(head, heads);
  if (!shownHead && !isKeyOrFile(head)) return english;
  const QString shownRest = engineText(rest);
  if (shownRest == rest) return english;  // never a translated head before an English sentence
  // "%1: %2": French puts a space before the colon.
  return QCoreApplication::translate("inlay::studio::EngineText", "%1: %2")
      .arg(shownHead.value_or(head), shownRest);
}

QStringList engineTexts(const QStringList& english) {
  QStringList out;
  for (const QString& e : english) out << engineText(e);
  return out;
}

namespace {

const std::vector<Pattern>& stagePatterns() {
  static const std::vector<Pattern> patterns = patternsOf(kStageTexts);
  return patterns;
}

// One part of a stage's text (a number, "3 passes" inside a longer part) in the language; as it
// is when no stage template matches it.
QString stagePart(const QString& english) {
  return translateWhole(english, stagePatterns(), stagePart).value_or(english);
}

// `text` split at each ", " outside parentheses: a part such as a curve's "(power 0.990, toe
// 0.000, shoulder 998)" stays whole.
QStringList splitOutsideParentheses(const QString& text, const QString& separator) {
  QStringList parts;
  qsizetype start = 0;
  int depth = 0;
  for (qsizetype i = 0; i < text.size(); ++i) {
    if (text[i] == QLatin1Char('(')) ++depth;
    else if (text[i] == QLatin1Char(')')) depth = std::max(0, depth - 1);
    else if (depth == 0 && QStringView(text).mid(i).startsWith(separator)) {
      parts << text.mid(start, i - start);
      start = i + separator.size();
      i = start - 1;
    }
  }
  parts << text.mid(start);
  return parts;
}

}  // namespace

QString engineStageText(const QString& english) {
  const QString separator = QStringLiteral(", ");
  QStringList parts = splitOutsideParentheses(english, separator);
  for (QString& part : parts) {
    // A scene key ("camera.response": the curve the file gave) reads the same in every language.
    if (!part.contains(QLatin1Char(' ')) && part.contains(QLatin1Char('.'))) continue;
    std::optional<QString> shown = translateWhole(part, stagePatterns(), stagePart);
    if (!shown) return english;  // never half translated
    part = *shown;
  }
  return parts.join(separator);
}

QStringList engineTemplates() {
  QStringList out;
  for (const char* s : kSentences) out << QString::fromUtf8(s);
  for (const char* s : kHeads) out << QString::fromUtf8(s);
  for (const char* s : kStageTexts) out << QString::fromUtf8(s);
  out << QStringLiteral("%1: %2");
  return out;
}

}  // namespace inlay::studio
