#include "board/config/text_file.h"

#include <fstream>
#include <sstream>

namespace deepnav {

bool readTextFile(const std::string& path, const std::string& what, std::string* text, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    if (error) *error = path + ": cannot open " + what;
    return false;
  }
  std::stringstream s;
  s << in.rdbuf();
  *text = s.str();
  return true;
}

}  // namespace deepnav
