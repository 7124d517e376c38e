// The scene file's [output] joint_colour: the default, each allowed value,
// and bad values as an InputError naming the file, the line, the key, the
// value and the allowed values.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "input/input_error.hpp"
#include "input/scene_file.hpp"
#include "support.hpp"

using namespace mortar::harness;
using namespace mortar::harness::testing;

namespace {

// The small wall's scene file with its joint at an absolute path and `output`
// as its [output] table.
std::string scene_with_output(const std::string& name, const std::string& output) {
  std::ifstream in(data_file("wall_small.toml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string joint = "joint = \"vdp_sn0.5.toml\"";
  REQUIRE(text.find(joint) != std::string::npos);
  text.replace(text.find(joint), joint.size(), "joint = \"" + data_file("vdp_sn0.5.toml") + "\"");
  return write_file(fresh_directory("scene_file") / name, text + "\n[output]\n" + output);
}

// The line number of the first line of `file` holding `text`.
int line_of(const std::string& file, const std::string& text) {
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(text) != std::string::npos) return n;
  return 0;
}

std::string error_of(const std::string& file) {
  try {
    read_scene_file(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("scene file: joint_colour defaults to the dissipation and reads each allowed value", "[scene_file]") {
  CHECK(read_scene_file(scene_with_output("none.toml", "every = 10\n")).output.joint_colour ==
        JointColour::dissipation);
  const std::pair<const char*, JointColour> values[] = {{"dissipation", JointColour::dissipation},
                                                        {"opening", JointColour::opening},
                                                        {"damage", JointColour::damage}};
  for (const auto& [name, colour] : values) {
    CAPTURE(name);
    const SceneSpec s = read_scene_file(scene_with_output("ok.toml", std::string("joint_colour = \"") + name + "\"\n"));
    CHECK(s.output.joint_colour == colour);
  }
}

TEST_CASE("scene file: a bad joint_colour names the file, line, key, value and the allowed values", "[scene_file]") {
  const std::string file = scene_with_output("bad.toml", "joint_colour = \"stress\"\n");
  const std::string message = error_of(file);
  CHECK_THAT(message, Catch::Contains(file + ":" + std::to_string(line_of(file, "joint_colour")) + ":") &&
                          Catch::Contains("[output] joint_colour = \"stress\" violates the rule: one of "
                                          "\"dissipation\", \"opening\", \"damage\""));
  // A value of the wrong type, and the British spelling's American twin as an unknown key.
  CHECK_THAT(error_of(scene_with_output("number.toml", "joint_colour = 3\n")),
             Catch::Contains("joint_colour") && Catch::Contains("string"));
  CHECK_THAT(error_of(scene_with_output("spelling.toml", "joint_color = \"damage\"\n")),
             Catch::Contains("unknown key 'joint_color'"));
}
