// The hardware port of an exported FMU (docs/FMI.md, "Export"). Its header is the host port's
// (ports/host/include/duet/hardware/hardware.hpp): every resource by its plant name, as doubles, converted as
// `duet sim` converts them. Where the host port hands the values to a plant, an FMU keeps them: what the model writes
// becomes the instance's outputs, what it reads comes from its inputs. The instance is the one whose step runs in
// this thread.

#include "duet/hardware/hardware.hpp"

#include "instance.hpp"

namespace duet::hardware {

void write(std::string_view resource, std::span<const double> values) {
  if (fmu::Instance* instance = fmu::Instance::current(); instance != nullptr)
    instance->write_resource(resource, values);
}

void read(std::string_view resource, std::span<double> values) {
  if (const fmu::Instance* instance = fmu::Instance::current(); instance != nullptr) {
    instance->read_resource(resource, values);
  }
}

}  // namespace duet::hardware
