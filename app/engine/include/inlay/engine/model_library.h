// The model library that ships with Inlay (resources/models, installed as share/inlay/models):
// library.json lists each piece with its .glb file, thumbnail, category, real size and default
// material; inlay-make-library (resources/models/generator) writes all of it.
#pragma once

#include "inlay/modeling/core.h"

#include <string>
#include <vector>

namespace inlay {

struct LibraryPiece {
  std::string name;       // id and file stem: "armchair"
  std::string title;      // English title, for users ("Armchair"; the studio translates it)
  std::string category;   // seating | tables | lighting | decor | storage | textiles
  std::string file;       // absolute path of the .glb
  std::string thumbnail;  // absolute path of the PNG thumbnail
  Vec3 sizeM{0, 0, 0};    // width (x), depth (z), height (y), metres
  std::string material;   // the default material in words
};

// The library folder: $INLAY_MODELS_DIR, else <exe>/../share/inlay/models (installed), else the
// source tree's resources/models (a build tree). Empty when none holds a library.json.
std::string modelLibraryDir();

// The pieces that `dir`/library.json lists, in its order. Errors name library.json, the key
// (pieces[3].dimensions_m.height) and the reason; a listed file that is missing is an error too.
Expected<std::vector<LibraryPiece>> loadModelLibrary(const std::string& dir);

}  // namespace inlay
