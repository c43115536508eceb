#include "duet/simulink_import/matlab_script.hpp"

#include <gtest/gtest.h>

#include <string>

#include "duet/simulink_import/yaml_variables.hpp"

namespace duet::simulink_import {
namespace {

Workspace run(std::string_view text, Workspace start = {}) {
  Result<Workspace> result = read_m_script(text, "params.m", std::move(start));
  EXPECT_TRUE(result.ok()) << result.error();
  return result.ok() ? std::move(result).value() : Workspace{};
}

std::string error_of(std::string_view text) {
  const Result<Workspace> result = read_m_script(text, "params.m");
  EXPECT_FALSE(result.ok()) << text;
  return result.ok() ? std::string{} : result.error();
}

TEST(MatlabScript, AssignmentsSeeEarlierNames) {
  const Workspace workspace = run("Kp = 0.5;\nKi = 2*Kp\nTs = 1e-3, N = 100;\n\nKd = Kp/N;");
  ASSERT_EQ(workspace.size(), 5U);
  EXPECT_EQ(workspace.at("Kp"), Value::scalar(0.5));
  EXPECT_EQ(workspace.at("Ki"), Value::scalar(1));
  EXPECT_EQ(workspace.at("Ts"), Value::scalar(1e-3));
  EXPECT_EQ(workspace.at("Kd"), Value::scalar(0.005));
}

TEST(MatlabScript, LaterAssignmentsReplaceEarlierOnes) {
  const Workspace workspace = run("x = 1; x = x + 1;", {{"y", Value::scalar(7)}});
  EXPECT_EQ(workspace.at("x"), Value::scalar(2));
  EXPECT_EQ(workspace.at("y"), Value::scalar(7));  // the start workspace is kept
}

TEST(MatlabScript, StructAssignmentsBuildStructs) {
  const Workspace workspace = run("P.wind.Kp = 2;\nP.wind.Ki = P.wind.Kp/4;\nP.Ts = 0.01;");
  const Value& parameters = workspace.at("P");
  ASSERT_TRUE(parameters.is_struct);
  ASSERT_NE(parameters.field("wind"), nullptr);
  EXPECT_EQ(*parameters.field("wind")->field("Kp"), Value::scalar(2));
  EXPECT_EQ(*parameters.field("wind")->field("Ki"), Value::scalar(0.5));
  EXPECT_EQ(*parameters.field("Ts"), Value::scalar(0.01));
}

TEST(MatlabScript, CommentsAndContinuations) {
  const Workspace workspace =
      run("% parameters of the balancing loop\n"
          "Kp = 3; % proportional\n"
          "%{\n"
          "Kp = 100;\n"
          "  %{\n"
          "  nested = 1;\n"
          "  %}\n"
          "%}\n"
          "A = [1 2 ...  the first row\n"
          "     3 4];\n"
          "B = [1 2\n"
          "     3 4];  % two rows\n"
          "s = Kp + ...\n"
          "    1;\n");
  EXPECT_EQ(workspace.at("Kp"), Value::scalar(3));
  EXPECT_EQ(workspace.at("A"), Value::matrix(1, 4, {1, 2, 3, 4}));
  EXPECT_EQ(workspace.at("B"), Value::matrix(2, 2, {1, 2, 3, 4}));
  EXPECT_EQ(workspace.at("s"), Value::scalar(4));
  EXPECT_EQ(workspace.count("nested"), 0U);
}

TEST(MatlabScript, EmptyScriptGivesTheStart) { EXPECT_TRUE(run("\n  \n% nothing\n;;\n").empty()); }

TEST(MatlabScript, RefusesWhatIsNotAnAssignment) {
  EXPECT_EQ(error_of("Kp = 1;\nload('params.mat')"),
            "params.m:2: 'load('params.mat')' is not an assignment; only assignments 'name = value' are supported");
  EXPECT_EQ(error_of("clear all"),
            "params.m:1: 'clear all' is not an assignment; only assignments 'name = value' are supported");
  EXPECT_EQ(error_of("initParams;"),
            "params.m:1: 'initParams' is not an assignment; only assignments 'name = value' are supported");
  EXPECT_EQ(error_of("x = 1;\nif x > 0\n y = 2;\nend"),
            "params.m:2: 'if' is not supported: only assignments 'name = value'");
  EXPECT_EQ(error_of("for k = 1:3\n end"), "params.m:1: 'for' is not supported: only assignments 'name = value'");
  EXPECT_EQ(error_of("x(2) = 5;"), "params.m:1: indexed assignment 'x(2) = 5' is not supported");
  EXPECT_EQ(error_of("[a, b] = deal(1, 2);"),
            "params.m:1: '[a, b] = deal(1, 2)' is not an assignment; only assignments 'name = value' are supported");
  EXPECT_EQ(error_of("x = 1;\nx.a = 2;"), "params.m:2: 'x' is not a struct, so 'x.a' cannot be assigned");
  EXPECT_EQ(error_of("%{\nx = 1;\n"), "params.m:1: block comment '%{' is not closed by '%}'");
}

TEST(MatlabScript, ExpressionProblemsNameLineAndColumn) {
  EXPECT_EQ(error_of("Kp = 1;\nKi = 2*Kx;"), "params.m:2:8: unresolved name 'Kx'");
  EXPECT_EQ(error_of("a = 1; b = (a + 2;"), "params.m:1:18: ')' expected");
  EXPECT_EQ(error_of("A = [1 2\n     3 x];"), "params.m:2:8: unresolved name 'x'");
  EXPECT_EQ(error_of("s = 'text';"), "params.m:1:5: character strings ('...') are not supported");
}

TEST(VariablesYaml, ReadsNumbersVectorsMatricesAndStructs) {
  const Result<Workspace> result = read_variables_yaml(DUET_SIMULINK_TESTING_DIR "/variables.yaml");
  ASSERT_TRUE(result.ok()) << result.error();
  const Workspace& workspace = result.value();
  EXPECT_EQ(workspace.at("Kp"), Value::scalar(0.5));
  EXPECT_EQ(workspace.at("Ts"), Value::scalar(1e-3));
  EXPECT_EQ(workspace.at("limit"), Value::scalar(std::numeric_limits<double>::infinity()));
  EXPECT_EQ(workspace.at("gains"), Value::matrix(1, 3, {1, 2, 3}));
  EXPECT_EQ(workspace.at("A"), Value::matrix(2, 2, {1, 0, 0.1, 1}));
  EXPECT_EQ(workspace.at("empty"), Value::matrix(0, 0, {}));
  EXPECT_EQ(*workspace.at("P").field("wind")->field("Ki"), Value::scalar(0.1));
}

std::string yaml_error(const std::string& name) {
  const std::string file = DUET_SIMULINK_TESTING_DIR "/" + name;
  const Result<Workspace> result = read_variables_yaml(file);
  EXPECT_FALSE(result.ok()) << name;
  if (result.ok()) return {};
  EXPECT_EQ(result.error().rfind(file + ":", 0), 0U) << result.error();
  return result.error().substr(file.size());
}

TEST(VariablesYaml, BadFilesSayLineAndProblem) {
  EXPECT_EQ(yaml_error("ragged.yaml"), ":2: the rows of 'rows' have different lengths (2 and 1)");
  EXPECT_EQ(yaml_error("not_a_number.yaml"), ":2: 'Ki' holds 'fast', not a number");
  EXPECT_EQ(yaml_error("twice.yaml"), ":2: 'Kp' is given twice");
  EXPECT_EQ(yaml_error("list.yaml"), ":1: expected a mapping of variable names to values");
  EXPECT_EQ(yaml_error("bad_name.yaml"), ":2: '2x' is not a MATLAB name (letters, digits and _, first a letter)");
  EXPECT_EQ(yaml_error("broken.yaml").substr(0, 3), ":2:");
  EXPECT_EQ(yaml_error("missing.yaml"), ": cannot open");
}

}  // namespace
}  // namespace duet::simulink_import
