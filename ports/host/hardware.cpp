#include "duet/hardware/hardware.hpp"

#include <algorithm>

#include "duet/plant/plant.hpp"

namespace duet::hardware {
namespace {

plant::Plant* connected = nullptr;

}  // namespace

void connect(plant::Plant* plant) { connected = plant; }

void write(std::string_view resource, std::span<const double> values) {
  if (connected != nullptr) connected->write(resource, values);
}

void read(std::string_view resource, std::span<double> values) {
  std::fill(values.begin(), values.end(), 0.0);
  if (connected != nullptr) connected->read(resource, values);
}

}  // namespace duet::hardware
