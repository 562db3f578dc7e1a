// A YAML mapping read key by key (core/yaml_section.h): each key is named once, where it is read,
// and a key nobody read is refused with the file, line and column and the keys that are known,
// in the order they were read.
#include "core/yaml_section.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"

namespace usvid {
namespace {

// The message of the InputError `read` throws on `text` ("" when it throws none).
template <typename F>
std::string Refusal(const std::string& text, F read) {
  const YAML::Node root = LoadYamlText(text, "ship.yaml");
  YamlSection top("ship.yaml", root, "");
  try {
    read(top);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlSectionTest, AnUnreadKeyIsRefusedWithTheKeysRead) {
  auto read = [](YamlSection& top) {
    (void)top.Text("name");
    (void)top.Number("rho");
    if (std::optional<YamlSection> hull = top.Child("hull")) {
      (void)hull->Number("L");
      (void)hull->Number("B");
      hull->RefuseUnknown();
    }
    top.RefuseUnknown();
  };
  EXPECT_EQ(Refusal("name: a\nrho: 1000\nhull: {L: 3, B: 0.5}\n", read), "");
  EXPECT_EQ(Refusal("name: a\nhull: {L: 3}\nspeed: 2\n", read),
            "ship.yaml:3:1: speed: unknown key (known: name, rho, hull)");
  EXPECT_EQ(Refusal("hull:\n  L: 3\n  draught: 0.2\n", read),
            "ship.yaml:3:3: hull.draught: unknown key (known: L, B)");
}

// A key asked for twice is listed once; one asked for but absent is still known.
TEST(YamlSectionTest, EachKeyIsListedOnceInTheOrderAsked) {
  auto read = [](YamlSection& top) {
    (void)top.Number("b");
    (void)top.Text("a");
    (void)top.Number("b");
    (void)top.Node("c");
    top.RefuseUnknown();
  };
  EXPECT_EQ(Refusal("z: 1\n", read), "ship.yaml:1:1: z: unknown key (known: b, a, c)");
}

}  // namespace
}  // namespace usvid
