// read_a2l on what other tools write (testing/engine.a2l): an /include, TYPEDEFs and INSTANCEs, AXIS_PTS, CURVE and
// MAP, conversions duet does not write, and what the reader leaves out, said as warnings.
#include <gtest/gtest.h>

#include <algorithm>

#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::xcp::host {
namespace {

std::string engine_file() { return std::string{DUET_A2L_TESTING} + "/engine.a2l"; }

class EngineA2l : public testing::Test {
 protected:
  void SetUp() override {
    auto read = read_a2l_file(engine_file());
    ASSERT_TRUE(read.ok()) << read.error();
    a2l = std::move(read).value();
  }

  const Variable& find(const std::vector<Variable>& variables, const std::string& name) {
    const auto found = std::find_if(variables.begin(), variables.end(),
                                    [&name](const Variable& variable) { return variable.name == name; });
    if (found == variables.end()) throw std::runtime_error{name + " was not read"};
    return *found;
  }
  const Variable& measurement(const std::string& name) { return find(a2l.measurements, name); }
  const Variable& characteristic(const std::string& name) { return find(a2l.characteristics, name); }

  A2lDescription a2l;
};

TEST_F(EngineA2l, ReadsConversionsAndUnitsFromAnIncludedFile) {
  EXPECT_EQ(measurement("engine_speed").conversion, (Conversion{0.25, 0}));  // RAT_FUNC raw = 4 * rpm
  EXPECT_EQ(measurement("engine_speed").unit, "rpm");
  EXPECT_EQ(measurement("coolant").conversion, (Conversion{0.5, -40}));
  EXPECT_EQ(measurement("coolant").unit, "degC");            // REF_UNIT, a UNIT in engine_units.a2l
  EXPECT_EQ(measurement("flags").conversion, Conversion{});  // NO_COMPU_METHOD
  EXPECT_EQ(measurement("cylinder_temperatures").count, 4U);
  EXPECT_EQ(measurement("cylinder_temperatures").dimensions, (std::vector<std::uint32_t>{2, 2}));
}

TEST_F(EngineA2l, ReadsNamedValuesFromAVerbalTable) {
  EXPECT_EQ(measurement("gear").labels, (std::vector<Label>{{0, "neutral"}, {1, "first"}, {2, "second"}}));
  EXPECT_TRUE(measurement("coolant").labels.empty());
}

TEST_F(EngineA2l, ExpandsInstancesOfStructuresIntoTheirMembers) {
  EXPECT_EQ(measurement("front_left.speed").address, 0x20001010U);
  EXPECT_EQ(measurement("front_left.slip").address, 0x20001012U);
  EXPECT_EQ(measurement("front_left.slip").type, DataType::uint16);
  EXPECT_EQ(characteristic("traction.gain").address, 0x20000400U);
  EXPECT_EQ(measurement("traction.wheel.speed").address, 0x20000402U);
  EXPECT_EQ(measurement("traction.wheel.slip").address, 0x20000404U);
}

TEST_F(EngineA2l, ReadsAxisPointsCurvesAndMaps) {
  const Variable& speeds = characteristic("speed_points");
  EXPECT_EQ(speeds.type, DataType::int16);
  EXPECT_EQ(speeds.count, 4U);
  EXPECT_EQ(speeds.address, 0x20000100U);

  // CURVE with its axis in the record: the count (1 byte), 8 points aligned to a word, then the values.
  const Variable& ignition = characteristic("ignition");
  ASSERT_EQ(ignition.axes.size(), 1U);
  EXPECT_EQ(ignition.count, 8U);
  EXPECT_EQ(ignition.address, 0x20000010U + 2 + 16);
  EXPECT_EQ(ignition.axes[0], (Axis{Axis::Kind::standard, "engine_speed", 8, "", DataType::int16, 0x20000012}));

  const Variable& fuel = characteristic("fuel");
  EXPECT_EQ(fuel.count, 12U);
  EXPECT_EQ(fuel.dimensions, (std::vector<std::uint32_t>{4, 3}));
  EXPECT_EQ(fuel.address, 0x20000200U);
  ASSERT_EQ(fuel.axes.size(), 2U);
  EXPECT_EQ(fuel.axes[0], (Axis{Axis::Kind::common, "engine_speed", 4, "speed_points", DataType::int16, 0x20000100}));
  EXPECT_EQ(fuel.axes[1],
            (Axis{Axis::Kind::common, "NO_INPUT_QUANTITY", 3, "load_points", DataType::int16, 0x20000108}));

  const Variable& limits = characteristic("limits");
  ASSERT_EQ(limits.axes.size(), 1U);
  EXPECT_EQ(limits.axes[0].kind, Axis::Kind::fixed);
  EXPECT_EQ(limits.count, 5U);
}

TEST_F(EngineA2l, ReadsTheXcpInterface) {
  EXPECT_EQ(a2l.epk, "engine 1.0 2026-11-26");
  EXPECT_EQ(a2l.epk_address, 0x8000U);
  EXPECT_EQ(a2l.max_cto, 8);
  EXPECT_EQ(a2l.identification_field, IdentificationField::relative_byte);
  EXPECT_EQ(a2l.max_odt_entry_size, 6);
  EXPECT_EQ(a2l.timestamp_size, 2);
  EXPECT_EQ(a2l.timestamp_unit, 5);
  EXPECT_EQ(a2l.checksum_type, ChecksumType::crc_32);
  ASSERT_EQ(a2l.events.size(), 2U);
  EXPECT_EQ(a2l.events[1].short_name, "crank");
  EXPECT_EQ(a2l.transport.host, "ecu.local");
}

TEST_F(EngineA2l, SaysWhatItLeavesOut) {
  const std::string file = engine_file();
  EXPECT_EQ(a2l.warnings, (std::vector<std::string>{
                              file + ":32:18: big-endian values (MSB_FIRST) are read as little-endian",
                              file + ":69:5: COMPU_METHOD pedal: TAB_INTP conversions are not applied (raw values)",
                              file + ":86:18: engine_speed: big-endian values (MSB_FIRST) are read as little-endian",
                              file + ":100:16: flags: BIT_MASK 0x0F is not applied (the whole value is read)",
                          }));
}

std::string engine_with(const std::string& from, const std::string& to) {
  auto text = read_text_file(engine_file());
  EXPECT_TRUE(text.ok());
  std::string changed = text.value();
  changed.replace(changed.find(from), from.size(), to);
  return changed;
}

TEST(A2lReader, AVerbalConversionNeedsItsWholeTable) {
  const auto missing = read_a2l(engine_with("COMPU_TAB_REF gear_table", "COMPU_TAB_REF gears"), engine_file());
  EXPECT_EQ(missing.error(), engine_file() + ":95:54: COMPU_METHOD gear_names: no COMPU_VTAB named 'gears'");
  const auto short_table = read_a2l(engine_with("TAB_VERB 3", "TAB_VERB 4"), engine_file());
  EXPECT_EQ(short_table.error(), engine_file() + ":63:51: COMPU_VTAB gear_table: 4 value pairs announced, 3 follow");
}

// A variable whose conversion the reader cannot apply says which (a recorder tells its reader that values are raw).
TEST_F(EngineA2l, AVariableSaysWhichConversionIsNotApplied) {
  const auto read = read_a2l(engine_with("UBYTE temperature 1 0.5", "UBYTE pedal 1 0.5"), engine_file());
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_EQ(find(read.value().measurements, "coolant").unapplied_conversion, "TAB_INTP");
  EXPECT_EQ(find(read.value().measurements, "engine_speed").unapplied_conversion, "");
  const auto curved = read_a2l(engine_with("COEFFS 0 4 0 0 0 1", "COEFFS 1 4 0 0 0 1"), engine_file());
  ASSERT_TRUE(curved.ok()) << curved.error();
  EXPECT_EQ(find(curved.value().measurements, "engine_speed").unapplied_conversion, "RAT_FUNC (not linear)");
}

TEST(A2lReader, AnIncludeItCannotFindIsAnErrorNamingTheFile) {
  const auto read = read_a2l(engine_with("engine_units.a2l", "units.a2l"), engine_file());
  EXPECT_EQ(read.error(),
            engine_file() + ":11:5: /include \"units.a2l\": cannot open " + DUET_A2L_TESTING + "/units.a2l");
  const auto looping = read_a2l_file(std::string{DUET_A2L_TESTING} + "/includes_itself.a2l");
  EXPECT_NE(looping.error().find("includes nest deeper than 16"), std::string::npos) << looping.error();
}

TEST(A2lReader, ReportsArraysOfStructuresVirtualMeasurementsAndUnknownBlocks) {
  std::string text = engine_with("/begin INSTANCE front_left \"the front left wheel\" wheel 0x20001010",
                                 "/begin INSTANCE front_left \"the front left wheel\" wheel 0x20001010 MATRIX_DIM 4");
  text.replace(text.find("BIT_MASK 0x0F"), 13, "/begin VIRTUAL coolant gear /end VIRTUAL");
  text.replace(text.find("/end MODULE"), 11, "/begin BLOB image \"\" 0x20000800 16 /end BLOB /end MODULE");
  const auto read = read_a2l(text, engine_file());
  ASSERT_TRUE(read.ok()) << read.error();
  const std::vector<std::string>& warnings = read.value().warnings;
  auto warned = [&warnings](const std::string& what) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&what](const std::string& warning) { return warning.ends_with(what); });
  };
  EXPECT_TRUE(warned("front_left: an array of structures (wheel) is not expanded"));
  EXPECT_TRUE(warned("flags: a VIRTUAL measurement (computed by the master) is left out"));
  EXPECT_TRUE(warned("BLOB is not read"));
  const auto& measurements = read.value().measurements;
  EXPECT_TRUE(std::none_of(measurements.begin(), measurements.end(), [](const Variable& variable) {
    return variable.name == "flags" || variable.name.starts_with("front_left");
  }));
}

}  // namespace
}  // namespace duet::xcp::host
