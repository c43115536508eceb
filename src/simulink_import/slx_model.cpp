#include "duet/simulink_import/slx_model.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>

namespace duet::simulink_import {
namespace {

constexpr std::string_view block_diagram = "simulink/blockdiagram.xml";
constexpr std::string_view root_system = "simulink/systems/system_root.xml";
// Subsystems nest; a file that nests deeper than any model does is refused rather than exhausting the stack.
constexpr int deepest_nesting = 100;

struct Problem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One parsed XML part, which knows where its nodes are for messages.
class XmlPart {
 public:
  XmlPart(std::string name, const std::string& text, const std::string& file) : name_(std::move(name)), text_(text) {
    const pugi::xml_parse_result parsed =
        document_.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed)
      throw Problem{file + ": " + name_ + ":" + std::to_string(line_at(parsed.offset)) +
                    ": not well-formed XML: " + parsed.description()};
  }
  [[nodiscard]] pugi::xml_node root() const { return document_.document_element(); }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] int line(pugi::xml_node node) const { return line_at(node.offset_debug()); }

 private:
  [[nodiscard]] int line_at(std::ptrdiff_t offset) const {
    const std::ptrdiff_t end = std::clamp<std::ptrdiff_t>(offset, 0, std::ssize(text_));
    return static_cast<int>(1 + std::count(text_.begin(), text_.begin() + end, '\n'));
  }
  std::string name_;
  const std::string& text_;
  pugi::xml_document document_;
};

// The <P Name="..."> children of `node`: name -> text.
std::map<std::string, std::string> p_children(pugi::xml_node node) {
  std::map<std::string, std::string> values;
  for (const pugi::xml_node p : node.children("P")) values[p.attribute("Name").value()] = p.child_value();
  return values;
}

// A whole number of a port, or nothing.
std::optional<int> port_number(std::string_view text) {
  int number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc{} || end != text.data() + text.size() || number < 1) return std::nullopt;
  return number;
}

class Reader {
 public:
  Reader(const Parts& parts, std::string file) : parts_(parts), file_(std::move(file)) {}

  SimulinkModel read() {
    const auto diagram_text = parts_.find(block_diagram);
    if (diagram_text == parts_.end()) {
      const bool json = parts_.count("simulink/blockDiagram.json") != 0;
      throw Problem{file_ + ": " +
                    (json ? std::string{"the block diagram is JSON (saved by R2026b or later), which duet does not "
                                        "read yet; save the model in an earlier release's format"}
                          : "no simulink/blockdiagram.xml: not a Simulink model package")};
    }
    const XmlPart& diagram = part(block_diagram);
    const pugi::xml_node information = diagram.root();
    const pugi::xml_node model_node = information.child("Model");
    if (!model_node) {
      const std::string what = information.child("Library") ? "a block library, not a model"
                               : information.child("Subsystem")
                                   ? "a subsystem reference file, not a model"
                                   : "no <Model> in <" + std::string{information.name()} + ">";
      throw Problem{where(diagram, information) + what};
    }
    SimulinkModel model;
    model.name = model_node.attribute("Name").value();
    if (model.name.empty()) model.name = p_children(model_node)["Name"];
    if (model.name.empty()) model.name = std::filesystem::path{file_}.stem().string();
    model.release = release();
    const bool split = parts_.count(root_system) != 0;
    model.format = split ? "slx (systems/)" : "slx (blockdiagram.xml)";
    const pugi::xml_node system = model_node.child("System");
    if (system && !system.attribute("Ref")) {
      model.root = read_system(diagram, system, 0);
    } else {
      const std::string reference = system ? system.attribute("Ref").value() : "system_root";
      model.root = read_referenced_system(reference, diagram, system ? system : model_node, 0);
    }
    read_defaults(model);
    model.solver = solver();
    return model;
  }

 private:
  const XmlPart& part(std::string_view name) {
    const auto found = parsed_.find(name);
    if (found != parsed_.end()) return *found->second;
    const auto text = parts_.find(name);
    if (text == parts_.end()) throw Problem{file_ + ": no part " + std::string{name}};
    auto parsed = std::make_unique<XmlPart>(std::string{name}, text->second, file_);
    return *parsed_.emplace(std::string{name}, std::move(parsed)).first->second;
  }

  [[nodiscard]] std::string where(const XmlPart& in, pugi::xml_node node) const {
    return file_ + ": " + in.name() + ":" + std::to_string(in.line(node)) + ": ";
  }

  std::string release() {
    const auto properties = parts_.find("metadata/coreProperties.xml");
    if (properties == parts_.end()) return {};
    const XmlPart& core = part("metadata/coreProperties.xml");
    for (const pugi::xml_node node : core.root().children()) {
      const std::string_view name = node.name();
      if (name == "version" || name.ends_with(":version")) return node.child_value();
    }
    return {};
  }

  System read_referenced_system(const std::string& reference, const XmlPart& from, pugi::xml_node at, int depth) {
    const std::string name = "simulink/systems/" + reference + ".xml";
    if (parts_.find(name) == parts_.end())
      throw Problem{where(from, at) + "the system " + reference + " has no part " + name};
    if (!reading_.insert(name).second) throw Problem{where(from, at) + "the system " + reference + " contains itself"};
    const XmlPart& system_part = part(name);
    const pugi::xml_node system = system_part.root();
    if (std::string_view{system.name()} != "System")
      throw Problem{where(system_part, system) + "the root element is <" + system.name() + ">, not <System>"};
    System read = read_system(system_part, system, depth);
    reading_.erase(name);
    return read;
  }

  System read_system(const XmlPart& in, pugi::xml_node node, int depth) {
    if (depth > deepest_nesting)
      throw Problem{where(in, node) + "subsystems nest deeper than " + std::to_string(deepest_nesting)};
    System system;
    system.part = in.name();
    std::map<std::string, std::string> name_of_sid;
    std::set<std::string> names;
    for (const pugi::xml_node block_node : node.children("Block")) {
      Block block = read_block(in, block_node, depth);
      if (!names.insert(block.name).second)
        throw Problem{where(in, block_node) + "a second block named '" + block.name + "' in this system"};
      if (!block.sid.empty()) name_of_sid[block.sid] = block.name;
      system.blocks.push_back(std::move(block));
    }
    for (const pugi::xml_node line_node : node.children("Line")) {
      Line line;
      line.name = p_children(line_node)["Name"];
      read_line_ends(in, line_node, name_of_sid, line, true);
      system.lines.push_back(std::move(line));
    }
    return system;
  }

  Block read_block(const XmlPart& in, pugi::xml_node node, int depth) {
    Block block;
    block.type = node.attribute("BlockType").value();
    block.name = node.attribute("Name").value();
    block.sid = node.attribute("SID").value();
    block.line = in.line(node);
    if (block.type.empty()) throw Problem{where(in, node) + "a block without BlockType"};
    if (block.name.empty()) throw Problem{where(in, node) + "a " + block.type + " block without a Name"};
    block.parameters = p_children(node);
    if (const pugi::xml_node counts = node.child("PortCounts")) {
      block.parameters["PortCounts"] = "[" + std::string{counts.attribute("in").as_string("0")} + ", " +
                                       std::string{counts.attribute("out").as_string("0")} + "]";
    }
    read_port_names(in, node, block);
    read_masks(node, block);
    const pugi::xml_node system = node.child("System");
    if (system) {
      block.systems.push_back(system.attribute("Ref")
                                  ? read_referenced_system(system.attribute("Ref").value(), in, system, depth + 1)
                                  : read_system(in, system, depth + 1));
    }
    return block;
  }

  // Signal names on output ports: <Port><P Name="PortNumber">1</P><P Name="Name">x</P></Port> up to R2022a, then
  // <PortProperties><Port Type="out" Index="1"><P Name="Name">x</P></Port></PortProperties>.
  void read_port_names(const XmlPart& in, pugi::xml_node node, Block& block) {
    const auto take = [&](pugi::xml_node port, std::string_view number) {
      std::map<std::string, std::string> values = p_children(port);
      if (values["Name"].empty()) return;
      const std::optional<int> index = port_number(number);
      if (!index) throw Problem{where(in, port) + "a port numbered '" + std::string{number} + "'"};
      block.output_names[*index] = values["Name"];
    };
    for (const pugi::xml_node port : node.children("Port")) {
      std::map<std::string, std::string> values = p_children(port);
      take(port, values.count("PortNumber") != 0 ? values["PortNumber"] : "1");
    }
    for (const pugi::xml_node port : node.child("PortProperties").children("Port")) {
      if (std::string_view{port.attribute("Type").value()} == "out") take(port, port.attribute("Index").value());
    }
  }

  // Mask values of each era, and a library link's: <Mask><MaskParameter Name><Value> (R2017b+), <Object
  // PropName="MaskObject"> with <Object PropName="Parameters"> (R2015a and before), <InstanceData> (links, R2017b+).
  static void read_masks(pugi::xml_node node, Block& block) {
    for (const pugi::xml_node parameter : node.child("Mask").children("MaskParameter")) {
      block.mask_parameters[parameter.attribute("Name").value()] = parameter.child("Value").child_value();
    }
    for (const pugi::xml_node object : node.children("Object")) {
      if (std::string_view{object.attribute("PropName").value()} != "MaskObject") continue;
      for (const pugi::xml_node parameter : object.children("Object")) {
        if (std::string_view{parameter.attribute("PropName").value()} != "Parameters") continue;
        std::map<std::string, std::string> values = p_children(parameter);
        block.mask_parameters[values["Name"]] = values["Value"];
      }
    }
    for (const auto& [name, value] : p_children(node.child("InstanceData"))) block.mask_parameters[name] = value;
  }

  // Src and Dst of a line and of its branches, which nest; only the leaves carry a Dst.
  void read_line_ends(const XmlPart& in, pugi::xml_node node, const std::map<std::string, std::string>& name_of_sid,
                      Line& line, bool top) {
    for (const pugi::xml_node p : node.children("P")) {
      const std::string_view name = p.attribute("Name").value();
      if (name == "Src" && top) line.source = endpoint(in, p, name_of_sid);
      if (name == "Dst") line.destinations.push_back(endpoint(in, p, name_of_sid));
    }
    for (const pugi::xml_node branch : node.children("Branch")) read_line_ends(in, branch, name_of_sid, line, false);
  }

  // "SID#kind:N" (N 1-based, 1 when left out).
  Endpoint endpoint(const XmlPart& in, pugi::xml_node p, const std::map<std::string, std::string>& name_of_sid) {
    const std::string_view text = p.child_value();
    const std::size_t hash = text.find('#');
    if (hash == std::string_view::npos || hash == 0)
      throw Problem{where(in, p) + "a line end '" + std::string{text} + "' is not SID#kind:port"};
    const std::string sid{text.substr(0, hash)};
    const auto block = name_of_sid.find(sid);
    if (block == name_of_sid.end())
      throw Problem{where(in, p) + "a line end names block SID " + sid + ", which this system does not have"};
    std::string_view rest = text.substr(hash + 1);
    const std::size_t colon = rest.find(':');
    Endpoint end{.block = block->second, .kind = std::string{rest.substr(0, colon)}, .port = 1};
    if (colon != std::string_view::npos) {
      const std::optional<int> port = port_number(rest.substr(colon + 1));
      if (!port) throw Problem{where(in, p) + "a line end '" + std::string{text} + "' has no port number after ':'"};
      end.port = *port;
    }
    if (end.kind.empty()) throw Problem{where(in, p) + "a line end '" + std::string{text} + "' has no port kind"};
    return end;
  }

  // BlockParameterDefaults: inside blockdiagram.xml up to R2015a, in bddefaults.xml R2017b to R2021b, nowhere after.
  void read_defaults(SimulinkModel& model) {
    for (const std::string_view name : {block_diagram, std::string_view{"simulink/bddefaults.xml"}}) {
      if (parts_.find(name) == parts_.end()) continue;
      const pugi::xml_node defaults = part(name).root().find_node(
          [](pugi::xml_node node) { return std::string_view{node.name()} == "BlockParameterDefaults"; });
      for (const pugi::xml_node block : defaults.children("Block")) {
        for (const auto& [parameter, value] : p_children(block))
          model.defaults[block.attribute("BlockType").value()][parameter] = value;
      }
    }
  }

  // The active configuration set's Simulink.SolverCC: a part of its own from R2015a (configSetInfo.xml says which),
  // inline in blockdiagram.xml before. A ConfigSetRef (settings in a data dictionary) leaves it empty.
  Solver solver() {
    std::string name{block_diagram};
    if (parts_.find("simulink/configSetInfo.xml") != parts_.end()) {
      const XmlPart& info = part("simulink/configSetInfo.xml");
      for (const pugi::xml_node set : info.root().children("ConfigSet")) {
        if (std::string_view{set.attribute("Active").value()} != "true") continue;
        std::string_view part_name = set.attribute("PartName").value();
        if (part_name.starts_with('/')) part_name.remove_prefix(1);
        name = part_name;
      }
    }
    if (parts_.find(name) == parts_.end()) return {};
    const pugi::xml_node solver = part(name).root().find_node([](pugi::xml_node node) {
      return std::string_view{node.name()} == "Object" &&
             std::string_view{node.attribute("ClassName").value()} == "Simulink.SolverCC";
    });
    return Solver{p_children(solver)};
  }

  const Parts& parts_;
  std::string file_;
  std::map<std::string, std::unique_ptr<XmlPart>, std::less<>> parsed_;
  std::set<std::string> reading_;  // the system parts being read, to refuse one that contains itself
};

}  // namespace

Result<SimulinkModel> read_slx_model(const Parts& parts, const std::string& file) {
  try {
    return Reader{parts, file}.read();
  } catch (const Problem& problem) {
    return Failure{problem.what()};
  }
}

}  // namespace duet::simulink_import
