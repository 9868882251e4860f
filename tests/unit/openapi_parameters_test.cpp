// api/openapi.yaml against the parameter declarations: every enum and numeric range that
// api/parameters.cpp says the document states is stated there, with the same values and default.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "api/openapi.hpp"
#include "api/parameters.hpp"

namespace lp::api {
namespace {

const YAML::Node& document() {
  static const YAML::Node doc = YAML::Load(std::string(openapi_document()));
  return doc;
}

// Follows "$ref" and an allOf of one "$ref" to the schema they name. (Nodes are moved with reset():
// assigning a YAML::Node writes into the node it refers to.)
YAML::Node child(const YAML::Node& node, const std::string& key) {
  return node[key];
}  // const: adds nothing

YAML::Node follow(YAML::Node node) {
  while (node.IsMap()) {
    const YAML::Node ref = child(node, "$ref"), all_of = child(node, "allOf");
    if (ref) {
      const std::string text = ref.as<std::string>();
      YAML::Node target = document();
      size_t start = 2;  // after "#/"
      while (start <= text.size()) {
        const size_t end = std::min(text.find('/', start), text.size());
        target.reset(child(target, text.substr(start, end - start)));
        start = end + 1;
      }
      node.reset(target);
    } else if (all_of && all_of.size() == 1) {
      node.reset(all_of[0]);
    } else {
      break;
    }
  }
  return node;
}

// In a list: "name=X" is the parameter named X, "type=X" the schema whose type property is the enum [X],
// a number the element at that index.
YAML::Node element(const YAML::Node& list, const std::string& key) {
  const size_t eq = key.find('=');
  if (eq == std::string::npos) return list[std::stoul(key)];
  const std::string field = key.substr(0, eq), value = key.substr(eq + 1);
  for (const auto& item : list) {
    const YAML::Node e = follow(item);
    const YAML::Node name = child(e, "name"), properties = child(e, "properties");
    if (field == "name" && name && name.as<std::string>() == value) return e;
    if (field != "type" || !properties || !child(properties, "type")) continue;
    const YAML::Node type_enum = child(child(properties, "type"), "enum");
    if (type_enum && type_enum.size() == 1 && type_enum[0].as<std::string>() == value) return e;
  }
  return YAML::Node(YAML::NodeType::Undefined);
}

YAML::Node locate(const std::vector<std::string>& location) {
  YAML::Node node = document();
  for (const std::string& key : location) {
    node.reset(follow(node));
    node.reset(node.IsSequence() ? element(node, key) : child(node, key));
    if (!node) return node;
  }
  return follow(node);
}

std::string where(const std::vector<std::string>& location) {
  std::string out;
  for (const auto& k : location) out += "/" + k;
  return out;
}

TEST(OpenApiParameters, EveryDeclaredEnumAndRangeIsTheDocumentedOne) {
  const auto parameters = documented_parameters();
  ASSERT_GT(parameters.size(), 40u);
  for (const DocumentedParameter& p : parameters) {
    SCOPED_TRACE(where(p.location));
    const YAML::Node schema = locate(p.location);
    ASSERT_TRUE(schema) << "not in api/openapi.yaml";
    if (!p.names.empty()) {
      EXPECT_EQ(schema["enum"].as<std::vector<std::string>>(), p.names);
    }
    if (p.minimum) {
      EXPECT_EQ(schema["minimum"].as<double>(), *p.minimum);
    }
    if (p.maximum) {
      ASSERT_TRUE(schema["maximum"]);
      EXPECT_EQ(schema["maximum"].as<double>(), *p.maximum);
    } else if (p.names.empty()) {
      EXPECT_FALSE(schema["maximum"]) << "the maximum is a server flag; the document must not fix one";
    }
    if (!p.fallback) {
      EXPECT_FALSE(schema["default"]);
    } else if (*p.fallback == "true" || *p.fallback == "false") {
      EXPECT_EQ(schema["type"].as<std::string>(), "boolean");
      ASSERT_TRUE(schema["default"]);
      EXPECT_EQ(schema["default"].as<bool>(), *p.fallback == "true");
    } else if (p.names.empty()) {
      ASSERT_TRUE(schema["default"]);
      EXPECT_FLOAT_EQ(float(schema["default"].as<double>()), float(std::stod(*p.fallback)));
    } else {
      EXPECT_EQ(schema["default"].as<std::string>(), *p.fallback);
    }
  }
}

}  // namespace
}  // namespace lp::api
