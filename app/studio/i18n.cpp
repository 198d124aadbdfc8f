#include "i18n.h"

#include "inlay/engine/data_dirs.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

#include <memory>

namespace inlay::studio {
namespace {

// Owned here so a second installTranslators() replaces rather than stacks catalogues.
std::unique_ptr<QTranslator>& qtTranslator() {
  static std::unique_ptr<QTranslator> t;
  return t;
}
std::unique_ptr<QTranslator>& ownTranslator() {
  static std::unique_ptr<QTranslator> t;
  return t;
}

// The installed catalogues (share/inlay/translations beside bin/): a language compiled into the
// program is taken from the program; one added later (a new .qm dropped there) from this folder.
QString installedTranslationsDir() { return QString::fromStdString(findDataDir("translations")); }

}  // namespace

QString chosenLanguage() {
  QString env = qEnvironmentVariable("INLAY_LANG").trimmed();
  if (!env.isEmpty()) return env;
  QString setting = QSettings().value(QStringLiteral("language")).toString().trimmed();
  if (!setting.isEmpty() && setting != QLatin1String("system")) return setting;
  // "de_DE" -> "de": our catalogues are per language, not per country.
  return QLocale::system().name().section(QLatin1Char('_'), 0, 0);
}

void removeTranslators() {
  for (auto* slot : {&qtTranslator(), &ownTranslator()}) {
    if (*slot) {
      QCoreApplication::removeTranslator(slot->get());
      slot->reset();
    }
  }
}

bool installTranslators(const QString& language) {
  removeTranslators();
  const QString lang = language.isEmpty() ? chosenLanguage() : language;
  if (lang.isEmpty() || lang == QLatin1String("en") || lang == QLatin1String("C")) return false;

  auto qt = std::make_unique<QTranslator>();
  if (qt->load(QStringLiteral("qtbase_") + lang, QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
    QCoreApplication::installTranslator(qt.get());
    qtTranslator() = std::move(qt);
  }
  auto own = std::make_unique<QTranslator>();
  const QString installed = installedTranslationsDir();
  if (own->load(QStringLiteral(":/i18n/inlay_") + lang + QStringLiteral(".qm")) ||
      (!installed.isEmpty() &&
       own->load(QStringLiteral("inlay_") + lang + QStringLiteral(".qm"), installed))) {
    QCoreApplication::installTranslator(own.get());
    ownTranslator() = std::move(own);
    return true;
  }
  return false;
}

}  // namespace inlay::studio
