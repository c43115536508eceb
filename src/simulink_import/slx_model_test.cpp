// The .slx reader on packages written here by hand as Simulink writes them (testing/slx_r2019b: the whole tree in
// blockdiagram.xml; testing/slx_r2022b: one part per system, PortCounts, a library link), the packaged text .mdl,
// and broken packages, each refused with its exact message.
#include "duet/simulink_import/slx_model.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "duet/fmi/archive_writer.hpp"
#include "duet/simulink_import/simulink_file.hpp"
#include "duet/simulink_import/slx_parts.hpp"
#include "duet/support/temporary_folder.hpp"
#include "duet/support/text_file.hpp"
#include "testing/package_folder.hpp"

namespace duet::simulink_import {
namespace {

const std::filesystem::path testing = DUET_SIMULINK_TESTING_DIR;

const Block& block(const System& system, const std::string& name) {
  for (const Block& each : system.blocks)
    if (each.name == name) return each;
  ADD_FAILURE() << "no block " << name;
  static const Block none;
  return none;
}

TEST(SlxModel, TheMonolithicLayoutWithItsMaskDefaultsAndActiveSolver) {
  auto model = read_slx_model(parts_of(testing / "slx_r2019b"), "tilt_loop.slx");
  ASSERT_TRUE(model) << model.error();
  EXPECT_EQ(model.value().name, "tilt_loop");
  EXPECT_EQ(model.value().release, "R2019b");
  EXPECT_EQ(model.value().format, "slx (blockdiagram.xml)");
  const System& root = model.value().root;
  EXPECT_EQ(root.part, "simulink/blockdiagram.xml");
  ASSERT_EQ(root.blocks.size(), 8U);
  EXPECT_EQ(block(root, "reference").parameters.at("Port"), "2");
  const Block& sum = block(root, "error");
  EXPECT_EQ(sum.type, "Sum");
  EXPECT_EQ(sum.sid, "3");
  EXPECT_EQ(sum.parameters.at("Inputs"), "|+-");
  EXPECT_EQ(sum.parameters.at("Ports"), "[2, 1]");
  EXPECT_EQ(sum.output_names.at(1), "e");
  EXPECT_EQ(block(root, "Proportional\nGain").parameters.at("Gain"), "Kp");  // &#xA; in the name
  const Block& scale = block(root, "Scale");
  EXPECT_EQ(scale.mask_parameters.at("k"), "2.5");
  ASSERT_EQ(scale.systems.size(), 1U);
  EXPECT_EQ(scale.systems[0].blocks.size(), 3U);
  EXPECT_EQ(block(scale.systems[0], "times k").parameters.at("Gain"), "k");
  ASSERT_EQ(scale.systems[0].lines.size(), 2U);

  ASSERT_EQ(root.lines.size(), 6U);
  const Line& into_sum = root.lines[0];
  ASSERT_TRUE(into_sum.source);
  EXPECT_EQ(into_sum.source->block, "theta");
  EXPECT_EQ(into_sum.source->kind, "out");
  ASSERT_EQ(into_sum.destinations.size(), 1U);
  EXPECT_EQ(into_sum.destinations[0].block, "error");
  EXPECT_EQ(into_sum.destinations[0].port, 2);
  const Line& branched = root.lines[3];  // two branches, one nested in another
  EXPECT_EQ(branched.name, "command");
  EXPECT_EQ(branched.source->block, "Proportional\nGain");
  ASSERT_EQ(branched.destinations.size(), 2U);
  EXPECT_EQ(branched.destinations[0].block, "Unit Delay");
  EXPECT_EQ(branched.destinations[1].block, "Scale");
  EXPECT_EQ(branched.destinations[1].kind, "in");

  EXPECT_EQ(model.value().defaults.at("Gain").at("Multiplication"), "Element-wise(K.*u)");
  EXPECT_EQ(model.value().defaults.at("UnitDelay").at("SampleTime"), "1");
  // The active set (configSet0), not the first listed.
  EXPECT_EQ(model.value().solver.parameters.at("SolverName"), "FixedStepDiscrete");
  EXPECT_EQ(model.value().solver.parameters.at("FixedStep"), "Ts");
  EXPECT_EQ(model.value().solver.parameters.at("EnableMultiTasking"), "on");
}

TEST(SlxModel, TheSystemsLayoutWithPortCountsPortPropertiesAndALibraryLink) {
  auto model = read_slx_model(parts_of(testing / "slx_r2022b"), "pid_loop.slx");
  ASSERT_TRUE(model) << model.error();
  EXPECT_EQ(model.value().name, "pid_loop");
  EXPECT_EQ(model.value().release, "R2022b");
  EXPECT_EQ(model.value().format, "slx (systems/)");
  const System& root = model.value().root;
  EXPECT_EQ(root.part, "simulink/systems/system_root.xml");
  const Block& pid = block(root, "Discrete PID Controller");
  EXPECT_EQ(pid.type, "Reference");
  EXPECT_EQ(pid.parameters.at("SourceType"), "PID 1dof");
  EXPECT_EQ(pid.parameters.at("PortCounts"), "[1, 1]");
  EXPECT_EQ(pid.mask_parameters.at("P"), "P.pid.Kp");
  EXPECT_EQ(pid.mask_parameters.at("TimeDomain"), "Discrete-time");
  const Block& limiter = block(root, "Limiter");
  ASSERT_EQ(limiter.systems.size(), 1U);
  EXPECT_EQ(limiter.systems[0].part, "simulink/systems/system_3.xml");
  EXPECT_EQ(block(limiter.systems[0], "Saturation").output_names.at(1), "limited");
  EXPECT_EQ(root.lines[1].name, "u");
  EXPECT_TRUE(model.value().defaults.empty());  // none written from R2022a on
  EXPECT_EQ(model.value().solver.parameters.at("FixedStep"), "0.001");
}

TEST(SlxParts, AnArchiveGivesItsTextPartsAndLeavesTheBinaryOnesOut) {
  auto folder = TemporaryFolder::make("slx_parts_test_").value();
  const Parts written = parts_of(testing / "slx_r2022b");
  std::vector<fmi::ArchiveInput> inputs;
  for (const auto& [name, text] : written) inputs.push_back({name, text});
  inputs.push_back({"simulink/bdmxdata/DataTag0.mxarray", std::string{"\x00\x01MAT", 5}});
  const std::filesystem::path slx = folder.path() / "pid_loop.slx";
  ASSERT_TRUE(fmi::write_archive(slx, inputs));
  auto parts = read_slx_parts(slx);
  ASSERT_TRUE(parts) << parts.error();
  std::vector<std::string> expected;
  for (const auto& [name, text] : written)
    if (name.ends_with(".xml")) expected.push_back(name);
  std::vector<std::string> names;
  for (const auto& [name, text] : parts.value()) names.push_back(name);
  EXPECT_EQ(names, expected);  // the .rels parts are not read either: the importer finds parts by path
  EXPECT_EQ(parts.value().at("simulink/systems/system_3.xml"), written.at("simulink/systems/system_3.xml"));

  const std::filesystem::path not_zip = folder.path() / "text.slx";
  std::ofstream{not_zip} << "Model {\n}\n";
  auto refused = read_slx_parts(not_zip);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error(), not_zip.string() + ": not a zip archive");
}

TEST(SlxParts, APackagedTextMdlCarriesTheSamePartsAsText) {
  const std::string bytes = read_text_file((testing / "packaged_r2025b.mdl").string()).value();
  ASSERT_TRUE(is_packaged_mdl(bytes));
  EXPECT_FALSE(is_packaged_mdl("Model {\n  Name \"m\"\n}\n"));
  auto parts = read_packaged_mdl_parts(bytes, "velo_pi.mdl");
  ASSERT_TRUE(parts) << parts.error();
  EXPECT_EQ(parts.value().size(), 3U);  // the BASE64 part is binary: left out
  EXPECT_TRUE(parts.value().at("simulink/blockdiagram.xml").starts_with("<?xml"));
  EXPECT_TRUE(parts.value().at("simulink/blockdiagram.xml").ends_with("</ModelInformation>"));
  auto model = read_slx_model(parts.value(), "velo_pi.mdl");
  ASSERT_TRUE(model) << model.error();
  EXPECT_EQ(model.value().name, "velo_pi");
  EXPECT_EQ(model.value().release, "R2025b");
  ASSERT_EQ(model.value().root.blocks.size(), 3U);
  EXPECT_EQ(model.value().root.blocks[1].parameters.at("Gain"), "0.8");
}

// The container is told by its bytes, not by its name.
TEST(SimulinkFile, EachContainerIsToldByItsBytes) {
  auto folder = TemporaryFolder::make("simulink_file_test_").value();
  std::vector<fmi::ArchiveInput> inputs;
  for (const auto& [name, text] : parts_of(testing / "slx_r2019b")) inputs.push_back({name, text});
  const std::filesystem::path slx = folder.path() / "tilt_loop.mdl";  // a misnamed .slx
  ASSERT_TRUE(fmi::write_archive(slx, inputs));
  auto zipped = read_simulink_file(slx);
  ASSERT_TRUE(zipped) << zipped.error();
  EXPECT_EQ(zipped.value().format, "slx (blockdiagram.xml)");
  EXPECT_EQ(zipped.value().root.blocks.size(), 8U);

  auto packaged = read_simulink_file(testing / "packaged_r2025b.mdl");
  ASSERT_TRUE(packaged) << packaged.error();
  EXPECT_EQ(packaged.value().format, "mdl (packaged text)");
  EXPECT_EQ(packaged.value().name, "velo_pi");

  auto classic = read_simulink_file(testing / "controller.mdl");
  ASSERT_TRUE(classic) << classic.error();
  EXPECT_EQ(classic.value().format, "mdl (classic)");

  auto missing = read_simulink_file(folder.path() / "none.slx");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("none.slx"), std::string::npos) << missing.error();
}

struct BrokenPackage {
  std::string label;
  Parts parts;
  std::string message;
};

std::string diagram(const std::string& model_children) {
  return "<?xml version=\"1.0\"?>\n<ModelInformation Version=\"1.0\">\n<Model Name=\"m\">\n" + model_children +
         "</Model>\n</ModelInformation>\n";
}

class BrokenSlx : public ::testing::TestWithParam<BrokenPackage> {};

TEST_P(BrokenSlx, IsRefusedWithThePartTheLineAndTheProblem) {
  auto model = read_slx_model(GetParam().parts, "m.slx");
  ASSERT_FALSE(model);
  EXPECT_EQ(model.error(), GetParam().message);
}

const std::string gain = "<Block BlockType=\"Gain\" Name=\"g\" SID=\"1\"/>\n";

INSTANTIATE_TEST_SUITE_P(
    Variants, BrokenSlx,
    ::testing::Values(
        BrokenPackage{"no_diagram",
                      {{"metadata/coreProperties.xml", "<x/>"}},
                      "m.slx: no simulink/blockdiagram.xml: not a Simulink model package"},
        BrokenPackage{"json_era",
                      {{"simulink/blockDiagram.json", "{}"}},
                      "m.slx: the block diagram is JSON (saved by R2026b or later), which duet does not read yet; "
                      "save the model in an earlier release's format"},
        BrokenPackage{
            "library",
            {{"simulink/blockdiagram.xml", "<ModelInformation>\n<Library Name=\"lib\"/>\n</ModelInformation>"}},
            "m.slx: simulink/blockdiagram.xml:1: a block library, not a model"},
        BrokenPackage{"not_xml",
                      {{"simulink/blockdiagram.xml", "<ModelInformation>\n<Model>\n</ModelInformation>"}},
                      "m.slx: simulink/blockdiagram.xml:3: not well-formed XML: Start-end tags mismatch"},
        BrokenPackage{"no_root_system",
                      {{"simulink/blockdiagram.xml", diagram("<System Ref=\"system_root\"/>\n")}},
                      "m.slx: simulink/blockdiagram.xml:4: the system system_root has no part "
                      "simulink/systems/system_root.xml"},
        BrokenPackage{"no_block_type",
                      {{"simulink/blockdiagram.xml", diagram("<System>\n<Block Name=\"g\"/>\n</System>\n")}},
                      "m.slx: simulink/blockdiagram.xml:5: a block without BlockType"},
        BrokenPackage{"no_name",
                      {{"simulink/blockdiagram.xml", diagram("<System>\n<Block BlockType=\"Gain\"/>\n</System>\n")}},
                      "m.slx: simulink/blockdiagram.xml:5: a Gain block without a Name"},
        BrokenPackage{"same_name",
                      {{"simulink/blockdiagram.xml", diagram("<System>\n" + gain + gain + "</System>\n")}},
                      "m.slx: simulink/blockdiagram.xml:6: a second block named 'g' in this system"},
        BrokenPackage{"unknown_sid",
                      {{"simulink/blockdiagram.xml",
                        diagram("<System>\n" + gain +
                                "<Line>\n<P Name=\"Src\">1#out:1</P>\n<P Name=\"Dst\">9#in:1</P>\n</Line>\n"
                                "</System>\n")}},
                      "m.slx: simulink/blockdiagram.xml:8: a line end names block SID 9, which this system does not "
                      "have"},
        BrokenPackage{"no_hash",
                      {{"simulink/blockdiagram.xml",
                        diagram("<System>\n" + gain + "<Line>\n<P Name=\"Src\">1out:1</P>\n</Line>\n</System>\n")}},
                      "m.slx: simulink/blockdiagram.xml:7: a line end '1out:1' is not SID#kind:port"},
        BrokenPackage{"bad_port",
                      {{"simulink/blockdiagram.xml",
                        diagram("<System>\n" + gain + "<Line>\n<P Name=\"Src\">1#out:x</P>\n</Line>\n</System>\n")}},
                      "m.slx: simulink/blockdiagram.xml:7: a line end '1#out:x' has no port number after ':'"},
        BrokenPackage{"no_kind",
                      {{"simulink/blockdiagram.xml",
                        diagram("<System>\n" + gain + "<Line>\n<P Name=\"Src\">1#:2</P>\n</Line>\n</System>\n")}},
                      "m.slx: simulink/blockdiagram.xml:7: a line end '1#:2' has no port kind"},
        BrokenPackage{"contains_itself",
                      {{"simulink/blockdiagram.xml", diagram("<System Ref=\"system_root\"/>\n")},
                       {"simulink/systems/system_root.xml",
                        "<System>\n<Block BlockType=\"SubSystem\" Name=\"s\" SID=\"1\">\n<System "
                        "Ref=\"system_1\"/>\n</Block>\n</System>"},
                       {"simulink/systems/system_1.xml",
                        "<System>\n<Block BlockType=\"SubSystem\" Name=\"t\" SID=\"2\">\n<System "
                        "Ref=\"system_1\"/>\n</Block>\n</System>"}},
                      "m.slx: simulink/systems/system_1.xml:3: the system system_1 contains itself"},
        BrokenPackage{"system_root_element",
                      {{"simulink/blockdiagram.xml", diagram("<System Ref=\"system_root\"/>\n")},
                       {"simulink/systems/system_root.xml", "<Systems/>"}},
                      "m.slx: simulink/systems/system_root.xml:1: the root element is <Systems>, not <System>"}),
    [](const ::testing::TestParamInfo<BrokenPackage>& variant) { return variant.param.label; });

TEST(SlxParts, BrokenPackagedTextIsRefusedWithItsLine) {
  const auto refused = [](const std::string& text) {
    auto parts = read_packaged_mdl_parts(text, "p.mdl");
    return parts ? std::string{"accepted"} : parts.error();
  };
  EXPECT_EQ(refused("Model {\n}\n"), "p.mdl: not a packaged text model (no __MWOPC_PACKAGE_BEGIN__)");
  EXPECT_EQ(refused("__MWOPC_PACKAGE_BEGIN__ R2025b\n__MWOPC_PART_BEGIN__ /a.xml\n<a/>\n"),
            "p.mdl: the package ends without __MWOPC_PACKAGE_END__ (truncated?)");
  EXPECT_EQ(refused("__MWOPC_PART_BEGIN__ /a.xml\n"), "p.mdl:1: a part before __MWOPC_PACKAGE_BEGIN__");
  EXPECT_EQ(refused("__MWOPC_PACKAGE_BEGIN__ R2025b\n__MWOPC_PART_BEGIN__ a.xml\n"),
            "p.mdl:2: a part without a name ('/...')");
  EXPECT_EQ(refused("__MWOPC_PACKAGE_BEGIN__\n__MWOPC_PART_BEGIN__ /a.xml\n<a/>\n__MWOPC_PART_BEGIN__ /a.xml\n"),
            "p.mdl:4: part /a.xml twice");
}

}  // namespace
}  // namespace duet::simulink_import
