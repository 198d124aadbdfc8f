// The Log dock's line for one stage of the preparation in the studio's language: the line
// inlay::describeStage() writes for `inlay-cli --verbose` ("camera: 0.840 s, CPU 1.520 s
// (estimated from the photo)", "shafts: skipped, no sun marked"), built from the same record
// with the stage's name, the frame and the lighting's steps translated here (context
// inlay::studio::StageText) and its reason or detail by engineStageText(). In English it is
// describeStage()'s line, character for character.
#pragma once

#include "inlay/engine/pipeline.h"

#include <QString>
#include <QStringList>

namespace inlay::studio {

QString stageLine(const StageRecord& stage);

// The stages' and the lighting's steps' names as the engine writes them (for the test that
// checks each is translated).
QStringList stageNames();

}  // namespace inlay::studio
