// What duet studio's page is shown of a model: the diagram's blocks, ports and wires, tasks and diagnostics, from
// the same reader and checker as duet model check.
#include "duet/studio/model_view.hpp"

#include <gtest/gtest.h>

#include "duet/studio/library.hpp"
#include "duet/support/text_file.hpp"

namespace duet::studio {
namespace {

using nlohmann::json;

json view_of(std::string_view text, const std::string& file = "m.yaml") {
  return model_view(check_text(text, file), text);
}

// What the diagram shows over every system: blocks (subsystems apart), subsystems, and wires.
struct DiagramCounts {
  std::size_t blocks = 0;
  std::size_t subsystems = 0;
  std::size_t wires = 0;
};

DiagramCounts count(const json& diagram) {
  DiagramCounts counts;
  auto visit = [&counts](const json& system, auto& self) -> void {
    counts.wires += system["wires"].size();
    for (const json& block : system["blocks"]) {
      if (!block.contains("system")) {
        ++counts.blocks;
        continue;
      }
      ++counts.subsystems;
      self(block["system"], self);
    }
  };
  visit(diagram["root"], visit);
  return counts;
}

const json* find_by(const json& list, const char* key, const std::string& value) {
  for (const json& entry : list) {
    if (entry[key] == value) return &entry;
  }
  return nullptr;
}

// A small model: a counter, a fan-out, and an edge-triggered subsystem with an input and an output port.
constexpr std::string_view small = R"(duet_model: 1
name: small
base_period_us: 1000
parameters:
  K: {value: 2, type: single, min: 0, max: 10, unit: V}
signals:
  x: {type: single, unit: V, measurable: true}
  doubled: {type: single, measurable: true}
blocks:
  # a comment between blocks
  - {name: source, type: Step, parameters: {time_s: 0.5, final: 1, type: single}, outputs: {y: x}}
  - name: scale
    type: Gain
    parameters: {k: K}
    inputs: {u: x}
    outputs: {y: doubled}

  - {name: high, type: Compare, parameters: {operator: ">", value: 0.5}, inputs: {u: x}, outputs: {y: is_high}}
  - name: latch
    type: Subsystem
    trigger: {edge: rising, signal: is_high}
    inputs: {value: doubled}
    outputs: {held: held}
    blocks:
      - {name: keep, type: Gain, parameters: {k: 1}, inputs: {u: value}, outputs: {y: held}}
  - {name: out, type: Outport, inputs: {u: held}}
)";

TEST(ModelView, DrawsEveryBlockWithItsPortsAndEverySignalAsAWire) {
  const json view = view_of(small);
  ASSERT_TRUE(view["ok"]) << view["diagnostics"].dump(2);
  const json& root = view["diagram"]["root"];
  EXPECT_EQ(root["path"], "");
  ASSERT_EQ(root["blocks"].size(), 5U);

  const json* scale = find_by(root["blocks"], "id", "scale");
  ASSERT_NE(scale, nullptr);
  EXPECT_EQ((*scale)["type"], "Gain");
  EXPECT_EQ((*scale)["line"], 12);
  EXPECT_EQ((*scale)["end_line"], 16);  // the blank line after it is not its
  EXPECT_EQ((*scale)["inputs"][0]["port"], "u");
  EXPECT_EQ((*scale)["inputs"][0]["signal"], "x");
  EXPECT_EQ((*scale)["inputs"][0]["line"], 15);
  EXPECT_EQ((*scale)["parameters"][0]["reference"], "K");
  EXPECT_TRUE((*scale)["parameters"][0]["tunable"]);

  const json* source = find_by(root["blocks"], "id", "source");
  EXPECT_EQ((*source)["end_line"], 11);  // a one-line flow-style block

  // x fans out to scale and high; its declaration gives its place, unit and type.
  const json* x = find_by(root["wires"], "signal", "x");
  ASSERT_NE(x, nullptr);
  EXPECT_EQ((*x)["id"], ":x");
  EXPECT_EQ((*x)["source"], (json{{"block", "source"}, {"port", "y"}}));
  EXPECT_EQ((*x)["targets"].size(), 2U);
  EXPECT_EQ((*x)["measurement"], "x");
  EXPECT_EQ((*x)["type"], "single");
  EXPECT_EQ((*x)["unit"], "V");
  EXPECT_EQ((*x)["line"], 7);
  // is_high is not measurable; it also reaches the subsystem's trigger port.
  const json* is_high = find_by(root["wires"], "signal", "is_high");
  ASSERT_NE(is_high, nullptr);
  EXPECT_TRUE((*is_high)["measurement"].is_null());
  EXPECT_EQ((*is_high)["targets"][0], (json{{"block", "latch"}, {"port", "trigger"}}));
}

TEST(ModelView, OpensASubsystemWithItsPortsAsTheInsidesWiresEnds) {
  const json view = view_of(small);
  const json* latch = find_by(view["diagram"]["root"]["blocks"], "id", "latch");
  ASSERT_NE(latch, nullptr);
  EXPECT_EQ((*latch)["trigger"]["kind"], "edge");
  EXPECT_EQ((*latch)["trigger"]["signal"], "is_high");
  ASSERT_EQ((*latch)["inputs"].size(), 2U);
  EXPECT_EQ((*latch)["inputs"][1]["kind"], "trigger");
  const json& inside = (*latch)["system"];
  EXPECT_EQ(inside["path"], "latch");
  EXPECT_EQ(inside["blocks"][0]["id"], "latch/keep");
  const json* value = find_by(inside["wires"], "signal", "value");
  ASSERT_NE(value, nullptr);
  EXPECT_EQ((*value)["id"], "latch:value");
  EXPECT_EQ((*value)["source"], (json{{"system_input", "value"}}));
  EXPECT_EQ((*value)["resolved"], "doubled");  // the parent's signal it stands for
  EXPECT_EQ((*value)["measurement"], "doubled");
  const json* held = find_by(inside["wires"], "signal", "held");
  ASSERT_NE(held, nullptr);
  EXPECT_EQ((*held)["targets"][0], (json{{"system_output", "held"}}));
  // The subsystem's blocks all run in the one task of its trigger's rate.
  EXPECT_EQ((*latch)["task"], inside["blocks"][0]["task"]);
}

TEST(ModelView, ListsTheTasksAndColoursEachBlockByItsTask) {
  const json view = view_of(small);
  ASSERT_EQ(view["tasks"].size(), 1U);
  EXPECT_EQ(view["tasks"][0]["kind"], "periodic");
  EXPECT_EQ(view["tasks"][0]["period_us"], 1000.0);
  EXPECT_EQ(view["tasks"][0]["function"], "step_rate_1");
  const json& root = view["diagram"]["root"];
  EXPECT_EQ((*find_by(root["blocks"], "id", "scale"))["task"], 0);
  const json& parameters = view["diagram"]["parameters"];
  ASSERT_EQ(parameters.size(), 1U);
  EXPECT_EQ(parameters[0]["name"], "K");
  EXPECT_EQ(parameters[0]["value"], "2");
  EXPECT_EQ(parameters[0]["max"], 10.0);
}

TEST(ModelView, TiesEachDiagnosticToTheBlockItIsIn) {
  std::string broken{small};
  broken.replace(broken.find("inputs: {u: x}\n    outputs: {y: doubled}"), 14, "inputs: {u: xx}");
  const json view = view_of(broken);
  EXPECT_FALSE(view["ok"]);
  ASSERT_FALSE(view["diagnostics"].empty());
  const json& first = view["diagnostics"][0];
  EXPECT_EQ(first["severity"], "error");
  EXPECT_EQ(first["line"], 15);
  EXPECT_EQ(first["block"], "scale");
  EXPECT_NE(first["message"].get<std::string>().find("xx"), std::string::npos);
  // The diagram is still drawn, without tasks: the model reads but does not check.
  ASSERT_FALSE(view["diagram"].is_null());
  EXPECT_TRUE(view["tasks"].empty());
  EXPECT_TRUE((*find_by(view["diagram"]["root"]["blocks"], "id", "scale"))["task"].is_null());
}

TEST(ModelView, AModelTooBrokenToReadHasNoDiagramButItsProblemsPlace) {
  const json view = view_of("duet_model: 1\nname: x\nblocks:\n  - {name: a, type: Gain\n");
  EXPECT_FALSE(view["ok"]);
  EXPECT_TRUE(view["diagram"].is_null());
  ASSERT_EQ(view["diagnostics"].size(), 1U);
  EXPECT_GT(view["diagnostics"][0]["line"].get<int>(), 1);
  EXPECT_TRUE(view["diagnostics"][0]["block"].is_null());
}

TEST(ModelView, DrawsTheRobotWithEveryBlockInEverySubsystem) {
  const std::string file = std::string{DUET_SOURCE_DIR} + "/apps/balbot/balbot.yaml";
  auto text = read_text_file(file);
  ASSERT_TRUE(text.ok());
  const json view = view_of(text.value(), file);
  ASSERT_TRUE(view["ok"]);
  const DiagramCounts counts = count(view["diagram"]);
  // duet model check counts 194: these and the edge detectors of its 12 edge-triggered subsystems.
  EXPECT_EQ(counts.blocks, 182U);
  EXPECT_EQ(counts.subsystems, 22U);
  EXPECT_EQ(counts.wires, 182U);  // as duet model check --json counts them from the file
  EXPECT_EQ(view["tasks"].size(), 11U);
  // Interrupt-triggered subsystems carry their interrupt; theta is measured on its wire.
  bool interrupt_found = false;
  for (const json& block : view["diagram"]["root"]["blocks"]) {
    if (block.contains("trigger") && block["trigger"]["kind"] == "interrupt") interrupt_found = true;
  }
  EXPECT_TRUE(interrupt_found);
  // A subsystem of a constant and the block it feeds runs in that block's task: the constant is computed once.
  const json* device_reset = find_by(view["diagram"]["root"]["blocks"], "id", "device_reset");
  ASSERT_NE(device_reset, nullptr);
  EXPECT_EQ((*device_reset)["system"]["blocks"][0]["task"], "constant");
  EXPECT_TRUE((*device_reset)["task"].is_number());
  const json* theta = find_by(view["diagram"]["root"]["wires"], "signal", "theta");
  ASSERT_NE(theta, nullptr);
  EXPECT_EQ((*theta)["measurement"], "theta");
}

TEST(Library, DescribesEveryBlockTypeWithItsParameters) {
  const json library = library_json();
  const json* gain = find_by(library, "type", "Gain");
  ASSERT_NE(gain, nullptr);
  EXPECT_EQ((*gain)["inputs"], json::array({"u"}));
  EXPECT_EQ((*gain)["parameters"][0]["name"], "k");
  EXPECT_TRUE((*gain)["parameters"][0]["required"]);
  EXPECT_FALSE((*gain)["summary"].get<std::string>().empty());
  const json* compare = find_by(library, "type", "Compare");
  EXPECT_EQ((*compare)["parameters"][0]["kind"], "word");
  EXPECT_EQ((*compare)["parameters"][0]["choices"].size(), 6U);
}

}  // namespace
}  // namespace duet::studio
