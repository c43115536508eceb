#include "duet/model/block_documentation.hpp"

#include <gtest/gtest.h>

#include "duet/model/block_types.hpp"

namespace duet::model {
namespace {

// The palette and the forms must know every block the checker knows, and nothing the checker does not.
TEST(BlockDocumentation, DocumentsEveryTypeAndEachOfItsParameters) {
  for (const BlockType& type : block_types()) {
    const BlockDocumentation* documentation = find_block_documentation(type.name);
    ASSERT_NE(documentation, nullptr) << type.name;
    EXPECT_FALSE(documentation->summary.empty()) << type.name;
    EXPECT_FALSE(documentation->category.empty()) << type.name;
    for (const ParameterSpec& parameter : type.parameters) {
      const ParameterDocumentation* described = find_parameter_documentation(*documentation, parameter.name);
      ASSERT_NE(described, nullptr) << type.name << '.' << parameter.name;
      EXPECT_FALSE(described->description.empty()) << type.name << '.' << parameter.name;
      // A word parameter is one the checker reads as a word; the others are numbers or references.
      EXPECT_EQ(described->kind != ParameterDocumentation::Kind::number, is_word_parameter(parameter.name))
          << type.name << '.' << parameter.name;
    }
    for (const ParameterDocumentation& described : documentation->parameters) {
      const bool known = std::any_of(type.parameters.begin(), type.parameters.end(),
                                     [&](const ParameterSpec& spec) { return spec.name == described.name; });
      EXPECT_TRUE(known) << type.name << " documents '" << described.name << "', which the checker does not take";
    }
  }
  EXPECT_EQ(find_block_documentation("Nonsense"), nullptr);
}

TEST(BlockDocumentation, GivesChoicesAndLimits) {
  const BlockDocumentation* compare = find_block_documentation("Compare");
  ASSERT_NE(compare, nullptr);
  const ParameterDocumentation* op = find_parameter_documentation(*compare, "operator");
  ASSERT_NE(op, nullptr);
  EXPECT_EQ(op->choices.size(), 6U);
  const ParameterDocumentation* window =
      find_parameter_documentation(*find_block_documentation("MovingAverage"), "window");
  ASSERT_NE(window, nullptr);
  EXPECT_TRUE(window->integer);
  EXPECT_EQ(window->minimum, 1.0);
  EXPECT_EQ(data_type_names().front(), "double");
}

}  // namespace
}  // namespace duet::model
