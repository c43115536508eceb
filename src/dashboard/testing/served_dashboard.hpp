#pragma once
// For tests: a back end's dashboard, described as a target would describe itself, serving on a thread of its own.

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <thread>
#include <utility>

#include "duet/dashboard/dashboard.hpp"

namespace duet::dashboard::testing {

class ServedDashboard {
 public:
  explicit ServedDashboard(Description description, std::optional<PlantControlAddress> plant_control = std::nullopt) {
    dashboard.emplace(io, ServerOptions{.log_name = "test"},
                      Backend{.set = [](Client&, const std::string&, double) {},
                              .describe = [](Client&) {},
                              .status = [] { return nlohmann::json::object(); }},
                      std::move(plant_control));
    EXPECT_TRUE(dashboard->start().ok());
    dashboard->describe(std::move(description));
    thread = std::thread{[this] { io.run(); }};
  }
  ~ServedDashboard() {
    boost::asio::post(io, [this] {
      dashboard->close();
      io.stop();
    });
    thread.join();
  }
  ServedDashboard(const ServedDashboard&) = delete;
  ServedDashboard& operator=(const ServedDashboard&) = delete;

  [[nodiscard]] std::uint16_t port() const { return dashboard->port(); }

  boost::asio::io_context io;
  std::optional<Dashboard> dashboard;
  std::thread thread;
};

}  // namespace duet::dashboard::testing
