// Model references (docs/MODELS.md, "Model references"): a Subsystem whose blocks come from another model file,
// bound through its Inports and Outports; and a model's Inports and Outports on its own, as plant resources.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"

namespace duet::model {
namespace {

// A folder of model files for one test, named after it.
class ModelFolder {
 public:
  ModelFolder() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = std::filesystem::path{::testing::TempDir()} / (std::string{"reference_"} + test->name());
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  ~ModelFolder() { std::filesystem::remove_all(folder_); }
  ModelFolder(const ModelFolder&) = delete;
  ModelFolder& operator=(const ModelFolder&) = delete;

  // Writes `text` as `name` in the folder; its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path path = folder_ / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream{path} << text;
    return path.string();
  }
  [[nodiscard]] std::string path(const std::string& name) const { return (folder_ / name).string(); }

 private:
  std::filesystem::path folder_;
};

// The referenced controller: a gain from a parameter, a state, a constant, a declared signal type.
constexpr const char* controller = R"(duet_model: 1
name: controller
base_period_us: 100
constants:
  half: 0.5
parameters:
  Kp: {value: 1.5, type: single}
signals:
  error: {type: single}
blocks:
  - {name: theta, type: Inport, outputs: {y: measured}}
  - {name: narrow, type: Convert, parameters: {type: single}, inputs: {u: measured}, outputs: {y: narrowed}}
  - {name: held, type: UnitDelay, inputs: {u: narrowed}, outputs: {y: before}}
  - {name: difference, type: Sum, parameters: {signs: "+-"}, inputs: {u1: narrowed, u2: before}, outputs: {y: error}}
  - {name: gain, type: Gain, parameters: {k: Kp}, inputs: {u: error}, outputs: {y: scaled}}
  - {name: halve, type: Gain, parameters: {k: half}, inputs: {u: scaled}, outputs: {y: command}}
  - {name: duty, type: Outport, inputs: {u: command}}
  - {name: spare, type: Outport, inputs: {u: before}}
)";

constexpr const char* top_header = R"(duet_model: 1
name: top
base_period_us: 100
signals:
  duty_command: {measurable: true}
blocks:
  - {name: count, type: Counter, parameters: {limit: 7}, outputs: {y: n}}
  - {name: ramp, type: Convert, parameters: {type: double}, inputs: {u: n}, outputs: {y: theta_measured}}
  - {name: on, type: Compare, parameters: {operator: '<', value: 5}, inputs: {u: n}, outputs: {y: enabled}}
)";

// The model, built; the diagnostics' text when it does not build.
struct Built {
  std::unique_ptr<Model> model = std::make_unique<Model>();
  std::optional<Program> program;
  std::string problems;
};

Built build(const std::string& path) {
  Built built;
  auto loaded = load_model(path);
  if (!loaded) {
    built.problems = loaded.error();
    return built;
  }
  *built.model = std::move(loaded).value();
  ProgramBuild program = build_program(*built.model);
  for (const Diagnostic& diagnostic : program.diagnostics) built.problems += format(path, diagnostic) + "\n";
  built.program = std::move(program.program);
  return built;
}

std::vector<double> simulated(const Built& built, const std::string& signal, plant::Plant& plant) {
  if (!built.program) return {};
  const auto result = simulate(*built.program, plant, {20 * 100e-6, {signal}, {}});
  if (!result) {
    ADD_FAILURE() << result.error();
    return {};
  }
  return result.value().recording.columns.at(0);
}

// The first problem of loading and building the model, without the folder's path.
std::string problem(const ModelFolder& folder, const std::string& name) {
  std::string text = build(folder.path(name)).problems;
  const auto replace = [&text](const std::string& what, const std::string& by) {
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + by.size())) {
      text.replace(at, what.size(), by);
    }
  };
  const std::string inside = folder.path("x");
  replace(inside.substr(0, inside.size() - 1), "");
  replace(inside.substr(0, inside.size() - 2), "DIR");
  return text.substr(0, text.find('\n'));
}

TEST(ModelReference, SimulatesBitForBitAsTheSameBlocksInline) {
  const ModelFolder folder;
  folder.write("parts/controller.yaml", controller);
  const std::string referencing = folder.write(
      "top.yaml", std::string{top_header} +
                      "  - {name: control, type: Subsystem, model: parts/controller.yaml, enable: enabled,\n"
                      "     inputs: {theta: theta_measured}, outputs: {duty: duty_command}}\n");
  const std::string inline_model = folder.write("inline.yaml", std::string{top_header} + R"(  - name: control
    type: Subsystem
    enable: enabled
    inputs: {measured: theta_measured}
    outputs: {command: duty_command}
    blocks:
      - {name: narrow, type: Convert, parameters: {type: single}, inputs: {u: measured}, outputs: {y: narrowed}}
      - {name: held, type: UnitDelay, inputs: {u: narrowed}, outputs: {y: before}}
      - {name: difference, type: Sum, parameters: {signs: "+-"}, inputs: {u1: narrowed, u2: before}, outputs: {y: error}}
      - {name: gain, type: Gain, parameters: {k: Kp}, inputs: {u: error}, outputs: {y: scaled}}
      - {name: halve, type: Gain, parameters: {k: half}, inputs: {u: scaled}, outputs: {y: command}}
constants:
  half: 0.5
parameters:
  Kp: {value: 1.5, type: single}
)");
  const Built referenced = build(referencing);
  const Built written_inline = build(inline_model);
  ASSERT_TRUE(referenced.program) << referenced.problems;
  ASSERT_TRUE(written_inline.program) << written_inline.problems;
  EXPECT_EQ(referenced.problems, "");
  // The referenced model's parameter is the model's, and its declaration types the signal inside the reference.
  EXPECT_EQ(referenced.model->parameters.at(0).name, "Kp");
  const auto error = referenced.program->find_signal("control/error");
  ASSERT_TRUE(error);
  EXPECT_EQ(referenced.program->signals[*error].type.type, DataType::float32);
  plant::Loopback first;
  plant::Loopback second;
  const std::vector<double> by_reference = simulated(referenced, "duty_command", first);
  EXPECT_EQ(by_reference.size(), 21U);
  EXPECT_EQ(by_reference, simulated(written_inline, "duty_command", second));
  EXPECT_NE(by_reference.at(3), 0.0);
}

TEST(ModelReference, ReferencesNestAndTheirParametersJoinOnce) {
  const ModelFolder folder;
  folder.write("controller.yaml", controller);
  folder.write("middle.yaml", R"(duet_model: 1
name: middle
base_period_us: 100
parameters:
  Kp: {value: 1.5, type: single}
blocks:
  - {name: u, type: Inport, outputs: {y: u}}
  - {name: inner, type: Subsystem, model: controller.yaml, inputs: {theta: u}, outputs: {duty: y}}
  - {name: y, type: Outport, inputs: {u: y}}
)");
  const std::string top = folder.write("top.yaml", std::string{top_header} +
                                                       "  - {name: outer, type: Subsystem, model: middle.yaml,"
                                                       " inputs: {u: theta_measured}, outputs: {y: duty_command}}\n");
  const Built built = build(top);
  ASSERT_TRUE(built.program) << built.problems;
  EXPECT_EQ(built.model->parameters.size(), 1U);
  EXPECT_TRUE(built.program->find_signal("outer/inner/error"));
  plant::Loopback plant;
  EXPECT_EQ(simulated(built, "duty_command", plant).at(2), 0.75);  // (2 - 1) * 1.5 * 0.5
}

struct Broken {
  std::string name;
  std::string referenced;  // controller.yaml's text, if there is one
  std::string reference;   // the reference's line in top.yaml, its last block
  std::string message;
  std::string after = {};  // top.yaml's lines after its blocks
};

void PrintTo(const Broken& broken, std::ostream* out) { *out << broken.name; }

class ModelReferenceErrors : public ::testing::TestWithParam<Broken> {};

TEST_P(ModelReferenceErrors, NameThePlaceAndTheProblem) {
  const ModelFolder folder;
  if (!GetParam().referenced.empty()) folder.write("controller.yaml", GetParam().referenced);
  folder.write("top.yaml", top_header + GetParam().reference + GetParam().after);
  EXPECT_EQ(problem(folder, "top.yaml"), GetParam().message);
}

constexpr const char* bound =
    "  - {name: c, type: Subsystem, model: controller.yaml, inputs: {theta: theta_measured}}\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, ModelReferenceErrors,
    ::testing::Values(
        Broken{"Missing", "", bound,
               "top.yaml:10:39: error: the model 'controller.yaml' that block 'c' references is not there (the path "
               "is relative to the referencing model's folder (DIR))"},
        Broken{"Unbound", controller, "  - {name: c, type: Subsystem, model: controller.yaml}\n",
               "top.yaml:10:39: error: the model 'controller.yaml' has an Inport that block 'c' does not bind: "
               "'theta' (bind every Inport to a signal: inputs: {theta: SIGNAL})"},
        Broken{"UnknownInport", controller,
               "  - {name: c, type: Subsystem, model: controller.yaml, inputs: {thet: theta_measured}}\n",
               "top.yaml:10:65: error: the model 'controller.yaml' has no Inport 'thet' (did you mean 'theta'?)"},
        Broken{"UnknownOutport", controller,
               "  - {name: c, type: Subsystem, model: controller.yaml, inputs: {theta: theta_measured},"
               " outputs: {torque: t}}\n",
               "top.yaml:10:99: error: the model 'controller.yaml' has no Outport 'torque' (its Outports: 'duty', "
               "'spare')"},
        Broken{"BasePeriod",
               "duet_model: 1\nname: c\nbase_period_us: 200\nblocks:\n  - {name: k, type: Constant, "
               "parameters: {value: 1}, outputs: {y: k}}\n",
               "  - {name: c, type: Subsystem, model: controller.yaml}\n",
               "top.yaml:10:39: error: the model 'controller.yaml' has base_period_us 200, the referencing model 100 "
               "(a reference runs at the referencing model's rates: give both the same base period)"},
        Broken{"NotAModel",
               "duet_model: 1\nname: c\nbase_period_us: 100\nblocks:\n  - {name: k, type: Constant, "
               "colour: red}\n",
               "  - {name: c, type: Subsystem, model: controller.yaml}\n",
               "top.yaml:10:39: error: the model 'controller.yaml' cannot be used: controller.yaml:5:31: error: "
               "unknown field 'colour' in block 'k' (known: name, type, period, period_us, parameters, inputs, "
               "outputs, blocks, trigger, enable, description, function, file, state, direct_feedthrough, model)"},
        Broken{"ItsOwnBlockIsWrong",
               "duet_model: 1\nname: c\nbase_period_us: 100\nblocks:\n  - {name: k, type: "
               "Constant, outputs: {y: k}}\n",
               "  - {name: c, type: Subsystem, model: controller.yaml}\n",
               "controller.yaml:5:5: error: block 'k' (Constant) needs parameter 'value' (parameters: {value: VALUE})"},
        Broken{"Itself", "", "  - {name: c, type: Subsystem, model: top.yaml}\n",
               "top.yaml:10:39: error: model reference cycle: top.yaml -> top.yaml (a model cannot contain itself, "
               "directly or through others)"},
        Broken{"ThroughAnother",
               "duet_model: 1\nname: c\nbase_period_us: 100\nblocks:\n  - {name: back, type: "
               "Subsystem, model: top.yaml}\n",
               "  - {name: c, type: Subsystem, model: controller.yaml}\n",
               "top.yaml:10:39: error: the model 'controller.yaml' cannot be used: controller.yaml:5:42: error: model "
               "reference cycle: top.yaml -> controller.yaml -> top.yaml (a model cannot contain itself, directly or "
               "through others)"},
        Broken{"ParameterDiffers", controller, bound,
               "top.yaml:10:39: error: 'Kp' is defined differently in controller.yaml:7:3 and top.yaml:12:3 (the "
               "models share parameters and constants by name: give both the same definition, or rename one)",
               "parameters:\n  Kp: {value: 2, type: single}\n"},
        Broken{"ConstantIsAParameterThere", controller, bound,
               "top.yaml:10:39: error: 'half' is defined differently in controller.yaml:5:3 and top.yaml:12:3 (the "
               "models share parameters and constants by name: give both the same definition, or rename one)",
               "parameters:\n  half: 0.5\n"}),
    [](const ::testing::TestParamInfo<Broken>& test) { return test.param.name; });

TEST(ModelInterface, InportsAndOutportsAreThePlantsResourcesOnTheirOwn) {
  const ModelFolder folder;
  const std::string path = folder.write("alone.yaml", R"(duet_model: 1
name: alone
base_period_us: 100
blocks:
  - {name: theta, type: Inport, parameters: {size: 2}, outputs: {y: theta}}
  - {name: twice, type: Gain, parameters: {k: 2}, inputs: {u: theta}, outputs: {y: doubled}}
  - {name: duty, type: Outport, inputs: {u: doubled}}
)");
  const Built built = build(path);
  ASSERT_TRUE(built.program) << built.problems;
  plant::Loopback plant;
  const std::vector<double> given{1.25, -3};
  plant.write("inport:theta", given);
  const std::vector<double> first_element = simulated(built, "doubled", plant);  // the recording's first column
  ASSERT_FALSE(first_element.empty());
  EXPECT_EQ(first_element.back(), 2.5);
  EXPECT_EQ(plant.value("outport:duty"), (std::vector<double>{2.5, -6}));
  EXPECT_EQ(plant.value("inport:theta"), given);  // read, not written
}

}  // namespace
}  // namespace duet::model
