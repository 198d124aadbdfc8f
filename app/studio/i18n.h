// Translations: Qt's own (qtbase_<lang>) and ours (:/i18n/inlay_<lang>.qm, compiled from
// translations/inlay_<lang>.ts and embedded in the studio library; a language not embedded is
// read from the installed share/inlay/translations/inlay_<lang>.qm).
//
// The language comes from, in order: the environment variable INLAY_LANG (tests, "de"), the
// setting "language" (QSettings; "" or "system" = follow the system), the system locale.
// GUI thread only; call before creating widgets.
#pragma once

#include <QString>

class QCoreApplication;

namespace inlay::studio {

// The language code the studio should use ("de", "en", ...).
QString chosenLanguage();

// Installs (replacing those installed by a previous call) Qt's translator and ours for
// `language` (empty: chosenLanguage()). Returns true when our own catalogue was found (always
// false for English, which needs none).
bool installTranslators(const QString& language = {});

// Removes the translators installed by installTranslators() (tests switch languages).
void removeTranslators();

}  // namespace inlay::studio
