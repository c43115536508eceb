// Reading model files: a whole model, and malformed ones, each with the message it must get.
#include "duet/model/model_file.hpp"

#include <gtest/gtest.h>

namespace duet::model {
namespace {

TEST(ModelFile, TheXcpSectionChangesTheSlavesDefaults) {
  const auto model = parse_model(R"(duet_model: 1
name: a
base_period_us: 100
xcp: {max_dto: 1024, daq_lists: 4, odts: 500, identification: relative_word_aligned, timestamp_bytes: 2,
      queue_bytes: 8192}
blocks:
  - {name: g, type: Gain}
)",
                                 "m.yaml");
  ASSERT_TRUE(model.ok()) << model.error();
  const XcpSettings& xcp = model.value().xcp;
  EXPECT_EQ(xcp.max_cto, 248U);  // a default
  EXPECT_EQ(xcp.max_dto, 1024U);
  EXPECT_EQ(xcp.daq_lists, 4U);
  EXPECT_EQ(xcp.odts, 500U);
  EXPECT_EQ(xcp.identification, "relative_word_aligned");
  EXPECT_EQ(xcp.timestamp_bytes, 2U);
  EXPECT_EQ(xcp.queue_bytes, 8192U);
  EXPECT_EQ(xcp.location.line, 4);
}

TEST(ModelFile, ReadsAWholeModel) {
  const auto model = parse_model(R"(duet_model: 1
name: step_time
description: The thesis' step-time test
base_period_us: 100
constants:
  n: 4096
parameters:
  Kp: {value: 0.0196, min: 0, max: 1, unit: "", description: proportional gain}
  A: {value: [[1, 1e-3], [0, 1]], type: single}
signals:
  theta: {type: single, unit: deg, measurable: true}
  buffer: {type: uint8, size: 12}
  state: {type: boolean, labels: [stopped, "running fast"]}
blocks:
  - {name: toggle, type: Not, inputs: {u: state_delayed}, outputs: {y: state}}
  - {name: delay, type: UnitDelay, period_us: 1000, parameters: {initial: false}, inputs: {u: state},
     outputs: {y: state_delayed}}
  - name: isr
    type: Subsystem
    trigger: {interrupt: DMA2_Stream2, priority: 6}
    inputs: {raw: buffer}
    blocks:
      - {name: gain, type: Gain, parameters: {k: Kp}, inputs: {u: raw}, outputs: {y: scaled}}
)",
                                 "step_time.yaml");
  ASSERT_TRUE(model.ok()) << model.error();
  const Model& m = model.value();
  EXPECT_EQ(m.name, "step_time");
  EXPECT_DOUBLE_EQ(m.base_period_us, 100);
  ASSERT_EQ(m.parameters.size(), 2U);
  EXPECT_EQ(m.parameters[1].type, DataType::float32);
  EXPECT_EQ(m.parameters[1].value.shape, (std::vector<std::size_t>{2, 2}));
  EXPECT_DOUBLE_EQ(m.parameters[1].value.elements[1], 1e-3);
  EXPECT_EQ(m.signals[1].shape, std::vector<std::size_t>{12});
  EXPECT_TRUE(m.signals[0].measurable);
  EXPECT_EQ(m.signals[2].labels, (std::vector<std::string>{"stopped", "running fast"}));
  ASSERT_EQ(m.blocks.size(), 3U);
  EXPECT_EQ(m.blocks[1].period.kind, Period::Kind::multiple);
  EXPECT_EQ(m.blocks[1].period.multiple, 10);
  EXPECT_DOUBLE_EQ(m.blocks[1].parameters[0].second.literal->elements[0], 0.0);  // false
  EXPECT_EQ(m.blocks[0].inputs[0].signal, "state_delayed");
  EXPECT_EQ(m.blocks[0].location.line, 15);
  EXPECT_EQ(m.blocks[2].trigger.kind, Trigger::Kind::interrupt);
  EXPECT_EQ(m.blocks[2].trigger.priority, 6);
  EXPECT_EQ(m.blocks[2].blocks[0].parameters[0].second.reference, "Kp");
}

struct Malformed {
  const char* name;
  const char* text;
  const char* message;
};

// Each malformed model and the one message it must get; none may crash the reader.
const Malformed corpus[] = {
    {"huge_size", "duet_model: 1\nname: a\nbase_period_us: 1\nparameters:\n  t: {value: 0, size: [100000, 100000]}\n",
     "m.yaml:5:23: error: a size of 10000000000 elements is more than 1000000 (a real-time core holds far less)"},
    {"not_yaml", "duet_model: 1\nblocks: [\n", "m.yaml:3:1: error: not YAML: end of sequence flow not found"},
    {"not_a_map", "- 1\n", "m.yaml:1:1: error: a model file is a map of fields (it starts with 'duet_model: 1')"},
    {"no_version", "name: a\n",
     "m.yaml:1:1: error: 'duet_model' is missing (the first line of a model is "
     "'duet_model: 1')"},
    {"future_version", "duet_model: 2\n", "m.yaml:1:13: error: this is duet model format 2; duet reads version 1"},
    {"unknown_field", "duet_model: 1\nnmae: a\n",
     "m.yaml:2:1: error: unknown field 'nmae' in the model (known: "
     "duet_model, name, description, base_period_us, precision, constants, "
     "parameters, signals, blocks, xcp)"},
    {"bad_name", "duet_model: 1\nname: 3dof\n",
     "m.yaml:2:7: error: the model name '3dof' is not a name (letters, "
     "digits and _, not starting with a digit)"},
    {"no_base", "duet_model: 1\nname: a\n",
     "m.yaml:1:1: error: 'base_period_us' is missing (the executive's tick, "
     "e.g. 100)"},
    {"negative_base", "duet_model: 1\nname: a\nbase_period_us: -5\n",
     "m.yaml:3:17: error: base_period_us must be more than 0"},
    {"no_blocks", "duet_model: 1\nname: a\nbase_period_us: 100\n", "m.yaml:1:1: error: 'blocks' is missing or empty"},
    {"block_without_type", "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g}\n",
     "m.yaml:5:5: error: block 'g' needs 'type'"},
    {"block_without_name", "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {type: Gain}\n",
     "m.yaml:5:5: error: a block needs 'name'"},
    {"block_unknown_field",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, input: {u: x}}\n",
     "m.yaml:5:27: error: unknown field 'input' in block 'g' (known: name, type, period, period_us, parameters, "
     "inputs, outputs, blocks, trigger, enable, description, function, file, state, direct_feedthrough, model)"},
    {"model_on_a_gain",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, model: c.yaml}\n",
     "m.yaml:5:34: error: 'model' belongs to Subsystem blocks (block 'g' is a Gain)"},
    {"model_and_blocks",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: s, type: Subsystem, model: c.yaml, blocks: "
     "[]}\n",
     "m.yaml:5:55: error: a model reference takes its blocks from its file (remove 'blocks')"},
    {"period_not_multiple",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, period_us: 150}\n",
     "m.yaml:5:38: error: period_us 150 is not a whole multiple of the base period (base_period_us is 100)"},
    {"period_both",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, period: base, "
     "period_us: 100}\n",
     "m.yaml:5:52: error: give 'period' or 'period_us', not both"},
    {"period_word", "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, period: fast}\n",
     "m.yaml:5:35: error: period must be base, inherited, constant or {multiple: N} (or give period_us)"},
    {"period_multiple_zero",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, period: {multiple: 0}}\n",
     "m.yaml:5:46: error: period: multiple must be a whole number >= 1"},
    {"bad_data_type",
     "duet_model: 1\nname: a\nbase_period_us: 100\nsignals:\n  x: {type: float}\nblocks:\n  - {name: g, type: Gain}\n",
     "m.yaml:5:13: error: unknown data type 'float' (double, single, int8, int16, int32, uint8, uint16, uint32 or "
     "boolean)"},
    {"bad_size",
     "duet_model: 1\nname: a\nbase_period_us: 100\nsignals:\n  x: {size: 0}\nblocks:\n  - {name: g, type: "
     "Gain}\n",
     "m.yaml:5:13: error: a size must be a whole number >= 1"},
    {"ragged_matrix",
     "duet_model: 1\nname: a\nbase_period_us: 100\nparameters:\n  A: [[1, 2], [3]]\nblocks:\n  - "
     "{name: g, type: Gain}\n",
     "m.yaml:5:15: error: parameter A: every row of a matrix needs 2 elements"},
    {"parameter_without_value",
     "duet_model: 1\nname: a\nbase_period_us: 100\nparameters:\n  K: {min: 0}\nblocks:\n "
     " - {name: g, type: Gain}\n",
     "m.yaml:5:6: error: parameter K needs 'value'"},
    {"value_outside_limits",
     "duet_model: 1\nname: a\nbase_period_us: 100\nparameters:\n  K: {value: 2, max: 1}\nblocks:"
     "\n  - {name: g, type: Gain}\n",
     "m.yaml:5:14: error: parameter K: the value is outside [min, max]"},
    {"min_above_max",
     "duet_model: 1\nname: a\nbase_period_us: 100\nparameters:\n  K: {value: 1, min: 2, max: 0}\n"
     "blocks:\n  - {name: g, type: Gain}\n",
     "m.yaml:5:22: error: parameter K: min is above max"},
    {"defined_twice",
     "duet_model: 1\nname: a\nbase_period_us: 100\nconstants:\n  K: 1\nparameters:\n  K: 2\nblocks:\n"
     "  - {name: g, type: Gain}\n",
     "m.yaml:7:3: error: 'K' is defined twice (constants and parameters share names)"},
    {"not_a_number",
     "duet_model: 1\nname: a\nbase_period_us: 100\nconstants:\n  K: [1, x2]\nblocks:\n  - {name: g, "
     "type: Gain}\n",
     "m.yaml:5:10: error: constant K must be a number (got 'x2')"},
    {"connection_to_list",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, inputs: "
     "{u: [a, b]}}\n",
     "m.yaml:5:39: error: a signal must be a name"},
    {"inputs_not_map", "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: g, type: Gain, inputs: [u]}\n",
     "m.yaml:5:35: error: inputs must be a map of fields"},
    {"bad_trigger",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: s, type: Subsystem, trigger: "
     "{timer: TIM2}}\n",
     "m.yaml:5:41: error: a trigger is {interrupt: NAME, priority: P} or {edge: rising|falling|either, signal: NAME}"},
    {"bad_priority",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: s, type: Subsystem, trigger: "
     "{interrupt: EXTI0, priority: high}}\n",
     "m.yaml:5:70: error: priority must be a whole number 0..255 or auto"},
    {"bad_edge",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: s, type: Subsystem, trigger: "
     "{edge: up, signal: x}}\n",
     "m.yaml:5:48: error: edge must be rising, falling or either"},
    {"edge_without_signal",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: s, type: Subsystem, "
     "trigger: {edge: rising}}\n",
     "m.yaml:5:41: error: an edge trigger needs 'signal'"},
    {"blocks_not_list",
     "duet_model: 1\nname: a\nbase_period_us: 100\nblocks:\n  - {name: s, type: Subsystem, blocks: "
     "{g: 1}}\n",
     "m.yaml:5:40: error: blocks must be a list"},
    {"xcp_unknown_field",
     "duet_model: 1\nname: a\nbase_period_us: 100\nxcp: {max_cro: 8}\nblocks:\n  - {name: g, type: Gain}\n",
     "m.yaml:4:7: error: unknown field 'max_cro' in xcp (known: max_cto, max_dto, daq_lists, odts, odt_entries, "
     "queue_bytes, download_bytes, identification, timestamp_bytes)"},
    {"xcp_cto_too_long",
     "duet_model: 1\nname: a\nbase_period_us: 100\nxcp: {max_cto: 256}\nblocks:\n  - {name: g, type: Gain}\n",
     "m.yaml:4:16: error: max_cto must be a whole number 8..255"},
    {"xcp_identification",
     "duet_model: 1\nname: a\nbase_period_us: 100\nxcp: {identification: relative}\nblocks:\n  - {name: g, type: "
     "Gain}\n",
     "m.yaml:4:23: error: identification must be absolute, relative_byte, relative_word or relative_word_aligned"},
    {"xcp_timestamp_of_three_bytes",
     "duet_model: 1\nname: a\nbase_period_us: 100\nxcp: {timestamp_bytes: 3}\nblocks:\n  - {name: g, type: Gain}\n",
     "m.yaml:4:24: error: timestamp_bytes must be 1, 2 or 4"},
    {"xcp_absolute_odts",
     "duet_model: 1\nname: a\nbase_period_us: 100\nxcp: {odts: 253}\nblocks:\n  - {name: g, type: Gain}\n",
     "m.yaml:4:13: error: odts must be at most 252 with absolute identification (an absolute ODT number is one byte "
     "below 0xFC; relative identification numbers ODTs per list)"},
    {"xcp_small_queue",
     "duet_model: 1\nname: a\nbase_period_us: 100\nxcp: {max_dto: 1000, queue_bytes: 1000}\nblocks:\n  - {name: g, "
     "type: Gain}\n",
     "m.yaml:4:35: error: queue_bytes must hold a DAQ packet and a response: at least 2004"},
    {"xcp_small_download",
     "duet_model: 1\nname: a\nbase_period_us: 100\nxcp: {download_bytes: 8}\nblocks:\n  - {name: g, type: Gain}\n",
     "m.yaml:4:23: error: download_bytes must hold one DOWNLOAD's data: at least max_cto - 2 = 246"},
    {"measurable_word",
     "duet_model: 1\nname: a\nbase_period_us: 100\nsignals:\n  x: {measurable: often}\nblocks:\n  - "
     "{name: g, type: Gain}\n",
     "m.yaml:5:19: error: measurable is true or false"},
    {"labels_of_a_float",
     "duet_model: 1\nname: a\nbase_period_us: 100\nsignals:\n  x: {type: single, labels: [a, b]}\nblocks:\n  - {name: "
     "g, type: Gain}\n",
     "m.yaml:5:29: error: signal x: only a boolean or an integer type names its values (declare its type)"},
    {"labels_of_a_boolean",
     "duet_model: 1\nname: a\nbase_period_us: 100\nsignals:\n  x: {type: boolean, labels: [a, b, c]}\nblocks:\n  - "
     "{name: g, type: Gain}\n",
     "m.yaml:5:30: error: signal x: a boolean has two labels, false's and true's"},
    {"labels_repeated",
     "duet_model: 1\nname: a\nbase_period_us: 100\nsignals:\n  x: {type: uint8, labels: [a, b, a]}\nblocks:\n  - "
     "{name: g, type: Gain}\n",
     "m.yaml:5:35: error: signal x: 'a' twice"},
    {"labels_alone",
     "duet_model: 1\nname: a\nbase_period_us: 100\nsignals:\n  x: {type: uint8, labels: [a]}\nblocks:\n  - {name: g, "
     "type: Gain}\n",
     "m.yaml:5:28: error: signal x: labels is a list of at least two names"},
};

class MalformedModel : public ::testing::TestWithParam<Malformed> {};

TEST_P(MalformedModel, GetsItsMessage) {
  const auto model = parse_model(GetParam().text, "m.yaml");
  ASSERT_FALSE(model.ok());
  EXPECT_EQ(model.error(), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(Corpus, MalformedModel, ::testing::ValuesIn(corpus),
                         [](const auto& test) { return std::string{test.param.name}; });

}  // namespace
}  // namespace duet::model
