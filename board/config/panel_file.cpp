#include "board/config/panel_file.h"

#include "board/config/text_file.h"
#include "board/config/yaml_document.h"
#include "vision/markers/aruco_dictionary.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace deepnav {
namespace {

struct Ctx {
  std::string name;
  std::string* error;
  bool fail(const std::string& key, const std::string& what) {
    if (error) *error = name + ": key '" + key + "' " + what;
    return false;
  }
};

bool readNumber(const YAML::Node& n, const std::string& key, double lo, double hi, double* out, Ctx& c) {
  if (!n || !n.IsScalar()) return c.fail(key, "is missing or not a number");
  try {
    *out = n.as<double>();
  } catch (const YAML::Exception&) {
    return c.fail(key, "is not a number");
  }
  if (!std::isfinite(*out) || *out < lo || *out > hi) {
    std::ostringstream s;
    s << "is " << *out << ", allowed [" << lo << ", " << hi << "]";
    return c.fail(key, s.str());
  }
  return true;
}

bool readVector(const YAML::Node& n, const std::string& key, int size, double* out, Ctx& c) {
  if (!n || !n.IsSequence() || static_cast<int>(n.size()) != size) {
    return c.fail(key, "must be a list of " + std::to_string(size) + " numbers");
  }
  for (int i = 0; i < size; ++i) {
    if (!readNumber(n[static_cast<std::size_t>(i)], key + "[" + std::to_string(i) + "]", -1e4, 1e4, &out[i], c)) {
      return false;
    }
  }
  return true;
}

bool checkKeys(const YAML::Node& n, const std::string& where, const std::set<std::string>& allowed, Ctx& c) {
  if (!n.IsMap()) return c.fail(where, "must be a map");
  for (const auto& kv : n) {
    const std::string k = kv.first.Scalar();
    if (!allowed.count(k)) return c.fail(where.empty() ? k : where + "." + k, "is unknown");
  }
  return true;
}

bool readFace(const YAML::Node& n, const std::string& key, PanelFace* f, Ctx& c) {
  if (!checkKeys(n, key, {"name", "centre_in_panel_m", "normal_in_panel", "width_m", "height_m"}, c)) return false;
  if (!n["name"] || !n["name"].IsScalar()) return c.fail(key + ".name", "is missing");
  f->name = n["name"].Scalar();
  double v[3];
  if (!readVector(n["centre_in_panel_m"], key + ".centre_in_panel_m", 3, v, c)) return false;
  f->centre_in_panel_m = Eigen::Vector3d(v[0], v[1], v[2]);
  if (!readVector(n["normal_in_panel"], key + ".normal_in_panel", 3, v, c)) return false;
  const Eigen::Vector3d normal(v[0], v[1], v[2]);
  if (normal.norm() < 1e-6) return c.fail(key + ".normal_in_panel", "must not be zero");
  f->normal_in_panel = normal.normalized();
  return readNumber(n["width_m"], key + ".width_m", 0.01, 100, &f->width_m, c) &&
         readNumber(n["height_m"], key + ".height_m", 0.01, 100, &f->height_m, c);
}

bool readMarker(const YAML::Node& n, const std::string& key, int faces, PanelMarker* m, Ctx& c) {
  if (!checkKeys(n, key, {"id", "face", "p_marker_in_panel_m", "q_panel_marker_xyzw"}, c)) return false;
  double id = 0, face = 0;
  if (!readNumber(n["id"], key + ".id", 0, 1023, &id, c) || !readNumber(n["face"], key + ".face", 0, faces - 1, &face, c)) {
    return false;
  }
  m->id = static_cast<int>(id);
  m->face = static_cast<int>(face);
  double p[3], q[4];
  if (!readVector(n["p_marker_in_panel_m"], key + ".p_marker_in_panel_m", 3, p, c) ||
      !readVector(n["q_panel_marker_xyzw"], key + ".q_panel_marker_xyzw", 4, q, c)) {
    return false;
  }
  m->p_marker_in_panel_m = Eigen::Vector3d(p[0], p[1], p[2]);
  const Eigen::Quaterniond quat(q[3], q[0], q[1], q[2]);
  if (std::abs(quat.norm() - 1.0) > 1e-3) return c.fail(key + ".q_panel_marker_xyzw", "must be a unit quaternion");
  m->q_panel_marker = quat.normalized();
  return true;
}

}  // namespace

bool parsePanelDescription(const std::string& text, const std::string& name, PanelDescription* out, std::string* error) {
  Ctx c{name, error};
  YAML::Node root;
  if (!parseYamlDocument(text, name, &root, error)) return false;
  if (!checkKeys(root, "", {"dictionary", "marker_size_m", "corner_radius_m", "faces", "markers"}, c)) return false;
  PanelDescription p;
  if (!root["dictionary"] || !root["dictionary"].IsScalar()) return c.fail("dictionary", "is missing");
  p.dictionary = root["dictionary"].Scalar();
  int dictionary_id = 0;  // the marker detector refuses an unknown one at start-up: say so here
  if (!arucoDictionaryFromName(p.dictionary, &dictionary_id)) {
    return c.fail("dictionary", "is '" + p.dictionary + "', not an ArUco dictionary (e.g. DICT_4X4_50)");
  }
  if (!readNumber(root["marker_size_m"], "marker_size_m", 0.01, 5, &p.marker_size_m, c) ||
      !readNumber(root["corner_radius_m"], "corner_radius_m", 0, 10, &p.corner_radius_m, c)) {
    return false;
  }
  const YAML::Node faces = root["faces"];
  if (!faces || !faces.IsSequence() || faces.size() == 0) return c.fail("faces", "must be a non-empty list");
  for (std::size_t i = 0; i < faces.size(); ++i) {
    PanelFace f;
    if (!readFace(faces[i], "faces[" + std::to_string(i) + "]", &f, c)) return false;
    p.faces.push_back(f);
  }
  const YAML::Node markers = root["markers"];
  if (!markers || !markers.IsSequence()) return c.fail("markers", "must be a list");
  std::set<int> ids;
  for (std::size_t i = 0; i < markers.size(); ++i) {
    PanelMarker m;
    const std::string key = "markers[" + std::to_string(i) + "]";
    if (!readMarker(markers[i], key, static_cast<int>(p.faces.size()), &m, c)) return false;
    if (!ids.insert(m.id).second) return c.fail(key + ".id", "repeats id " + std::to_string(m.id));
    p.markers.push_back(m);
  }
  *out = p;
  return true;
}

bool loadPanelDescription(const std::string& path, PanelDescription* out, std::string* error) {
  std::string text;
  return readTextFile(path, "the panel description", &text, error) && parsePanelDescription(text, path, out, error);
}

std::string formatPanelDescription(const PanelDescription& p) {
  std::ostringstream s;
  s.precision(17);
  s << "# Panel description (knowledge base). Frames: panel P (origin at the footprint centre on the seabed,\n"
       "# x = front face normal, y = left face normal, z up); marker M (ArUco: x right, y up, z out of the face).\n";
  s << "dictionary: " << p.dictionary << "\nmarker_size_m: " << p.marker_size_m
    << "\ncorner_radius_m: " << p.corner_radius_m << "\nfaces:\n";
  for (const auto& f : p.faces) {
    s << "  - {name: " << f.name << ", centre_in_panel_m: [" << f.centre_in_panel_m.x() << ", "
      << f.centre_in_panel_m.y() << ", " << f.centre_in_panel_m.z() << "], normal_in_panel: ["
      << f.normal_in_panel.x() << ", " << f.normal_in_panel.y() << ", " << f.normal_in_panel.z()
      << "], width_m: " << f.width_m << ", height_m: " << f.height_m << "}\n";
  }
  s << "markers:\n";
  for (const auto& m : p.markers) {
    const auto& q = m.q_panel_marker;
    s << "  - {id: " << m.id << ", face: " << m.face << ", p_marker_in_panel_m: [" << m.p_marker_in_panel_m.x()
      << ", " << m.p_marker_in_panel_m.y() << ", " << m.p_marker_in_panel_m.z() << "], q_panel_marker_xyzw: ["
      << q.x() << ", " << q.y() << ", " << q.z() << ", " << q.w() << "]}\n";
  }
  return s.str();
}

bool writePanelDescription(const std::string& path, const PanelDescription& panel, std::string* error) {
  std::ofstream out(path);
  out << formatPanelDescription(panel);
  if (!out) {
    if (error) *error = path + ": cannot write the panel description";
    return false;
  }
  return true;
}

}  // namespace deepnav
