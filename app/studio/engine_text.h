// The engine's messages (preparation warnings, refused model and scene files, the lighting's
// notes) in the studio's language. The engine is shared with the command line, which stays
// English, and does not depend on Qt: it says what happened in English sentences built from a
// fixed set of templates ("more than %1 triangles", "lights: none given; ..."). The studio
// knows those templates (engine_text.cpp lists them for lupdate, context
// inlay::studio::EngineText) and translates a message by matching it against them, the parts
// that vary (numbers, keys, file names, nested reasons) carried over as arguments.
//
// A message is read as "HEAD: REST" chains the way the engine builds them (Error::message():
// file, key, reason; "lighting: " + note): a head that is a file name or a scene key
// ("objects[1].mesh", "shafts[0]") stays, a known head ("line %1", "lighting") is translated,
// and the rest is translated in turn. A message no template matches stays as it is (English),
// never garbled. GUI thread or any thread: it only reads the installed translators.
#pragma once

#include <QString>
#include <QStringList>

namespace inlay::studio {

// `english` (one engine message) in the current language.
QString engineText(const QString& english);
QStringList engineTexts(const QStringList& english);

// The reason a preparation stage was skipped, or what it did (StageRecord::reason, ::detail:
// parts joined by ", ", each a template of its own: "1 light, 0 suns, 5 passes, ..."), in the
// current language; as it is (English) when one part matches no template.
QString engineStageText(const QString& english);

// The templates as the engine writes them (for the test that checks every one is translated).
QStringList engineTemplates();

}  // namespace inlay::studio
