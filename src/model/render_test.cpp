// The block diagram in Graphviz's language.
#include "duet/model/render.hpp"

#include <gtest/gtest.h>

#include "duet/model/model_file.hpp"

namespace duet::model {
namespace {

TEST(Render, BlocksPortsConnectionsAndSubsystems) {
  const auto model = parse_model(R"(duet_model: 1
name: diagram
base_period_us: 100
blocks:
  - {name: count, type: Counter, parameters: {limit: 7}, outputs: {y: n}}
  - {name: handover, type: RateTransition, inputs: {u: n}, outputs: {y: newest}}
  - name: capture
    type: Subsystem
    trigger: {interrupt: TIM2, priority: 3}
    inputs: {level: newest}
    blocks:
      - {name: led, type: GpioOut, parameters: {pin: PB0}, inputs: {u: level}}
)",
                                 "m.yaml");
  ASSERT_TRUE(model.ok()) << model.error();
  const std::string dot = to_dot(model.value());
  EXPECT_EQ(dot.rfind("digraph \"diagram\" {", 0), 0U);
  EXPECT_NE(dot.find("\"count\" [label=\"{count\\nCounter|{<y> y}}\"];"), std::string::npos) << dot;
  EXPECT_NE(dot.find("subgraph \"cluster_capture\" {"), std::string::npos) << dot;
  EXPECT_NE(dot.find("label=\"capture (interrupt TIM2, priority 3)\""), std::string::npos) << dot;
  // Across the subsystem's border, the arrow goes to the block inside.
  EXPECT_NE(dot.find("\"handover\":\"y\" -> \"capture/led\":\"u\" [label=\"newest\"];"), std::string::npos) << dot;
  EXPECT_NE(dot.find("\"count\":\"y\" -> \"handover\":\"u\" [label=\"n\"];"), std::string::npos) << dot;
}

}  // namespace
}  // namespace duet::model
