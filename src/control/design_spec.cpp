#include "duet/control/design_spec.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "duet/control/balbot_model.hpp"
#include "duet/control/riccati.hpp"
#include "duet/support/text_file.hpp"

namespace duet::control {
namespace {

std::string size_text(const Eigen::MatrixXd& m) { return std::to_string(m.rows()) + "x" + std::to_string(m.cols()); }

// "unknown field 'x' (known: a, b)".
std::string unknown_field(const std::string& key, const std::vector<std::string>& known) {
  std::string message = "unknown field '" + key + "' (known: ";
  for (const std::string& name : known) message += (&name == &known.front() ? "" : ", ") + name;
  return message + ")";
}

// Reads values and says where a problem is: "file:line:column: what".
class SpecReader {
 public:
  explicit SpecReader(std::string file) : file_(std::move(file)) {}

  [[nodiscard]] std::string place(const YAML::Node& node) const {
    const YAML::Mark mark = node.Mark();
    if (mark.is_null()) return file_;
    return file_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
  }
  [[nodiscard]] Failure at(const YAML::Node& node, const std::string& what) const {
    return Failure{place(node) + ": " + what};
  }

  [[nodiscard]] std::optional<Failure> only(const YAML::Node& map, const std::string& where,
                                            std::initializer_list<const char*> known) const {
    for (const auto& entry : map) {
      const auto key = entry.first.as<std::string>();
      bool found = false;
      for (const char* name : known) found = found || key == name;
      if (!found) return at(entry.first, where + unknown_field(key, {known.begin(), known.end()}));
    }
    return std::nullopt;
  }

  [[nodiscard]] Result<double> number(const YAML::Node& node, const std::string& what) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
      return at(node, what + ": expected a number, got " +
                          (node.IsScalar() ? "'" + node.Scalar() + "'"
                           : node.IsNull() ? "nothing"
                                           : "a list or map"));
    }
    return value;
  }

  // A number (1x1), a list of rows, or {diagonal: [numbers]}.
  [[nodiscard]] Result<Eigen::MatrixXd> matrix(const YAML::Node& node, const std::string& key) const {
    if (node.IsScalar()) {
      auto value = number(node, key);
      if (!value) return Failure{value.error()};
      return Eigen::MatrixXd{Eigen::MatrixXd::Constant(1, 1, value.value())};
    }
    if (node.IsMap()) {
      if (auto unknown = only(node, key + ": ", {"diagonal"})) return *unknown;
      const YAML::Node diagonal = node["diagonal"];
      if (!diagonal || !diagonal.IsSequence() || diagonal.size() == 0) {
        return at(node, key + ": diagonal: expected a list of numbers");
      }
      Eigen::VectorXd values(static_cast<Eigen::Index>(diagonal.size()));
      for (std::size_t i = 0; i < diagonal.size(); ++i) {
        auto value = number(diagonal[i], key + ": diagonal");
        if (!value) return Failure{value.error()};
        values(static_cast<Eigen::Index>(i)) = value.value();
      }
      return Eigen::MatrixXd{values.asDiagonal()};
    }
    if (!node.IsSequence() || node.size() == 0 || !node[0].IsSequence() || node[0].size() == 0) {
      return at(node,
                key + ": expected a matrix as a list of rows: [[1, 0], [0, 1]]; a row [[1, 2]], a column [[1], [2]]");
    }
    const std::size_t columns = node[0].size();
    Eigen::MatrixXd result(static_cast<Eigen::Index>(node.size()), static_cast<Eigen::Index>(columns));
    for (std::size_t row = 0; row < node.size(); ++row) {
      const YAML::Node numbers = node[row];
      const std::string where = key + ": row " + std::to_string(row + 1);
      if (!numbers.IsSequence())
        return at(numbers, where + ": expected a list of numbers (a matrix is a list of rows)");
      if (numbers.size() != columns) {
        return at(numbers,
                  where + " has " + std::to_string(numbers.size()) + " numbers; row 1 has " + std::to_string(columns));
      }
      for (std::size_t column = 0; column < columns; ++column) {
        auto value = number(numbers[column], where);
        if (!value) return Failure{value.error()};
        result(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(column)) = value.value();
      }
    }
    return result;
  }

 private:
  std::string file_;
};

// A matrix given under its continuous-time name ("A") or its discrete-time name ("Ad").
struct Named {
  std::string key;
  YAML::Node node;
};

Result<std::optional<Named>> either(const SpecReader& reader, const YAML::Node& root, const std::string& key) {
  const std::string discrete = key + "d";
  if (root[key] && root[discrete])
    return reader.at(root[discrete], "give '" + key + "' or '" + discrete + "', not both");
  if (root[key]) return std::optional<Named>{Named{key, root[key]}};
  if (root[discrete]) return std::optional<Named>{Named{discrete, root[discrete]}};
  return std::optional<Named>{};
}

Result<BalbotParameters> read_balbot(const SpecReader& reader, const YAML::Node& node) {
  if (!node.IsMap())
    return reader.at(node, "balbot: expected a map of the robot's parameters (or {} for the defaults)");
  BalbotParameters robot;
  const std::pair<const char*, double BalbotParameters::*> numbers[] = {
      {"wheel_mass", &BalbotParameters::wheel_mass},
      {"body_mass", &BalbotParameters::body_mass},
      {"axle_to_centre_of_mass", &BalbotParameters::axle_to_centre_of_mass},
      {"body_depth", &BalbotParameters::body_depth},
      {"wheel_radius", &BalbotParameters::wheel_radius},
      {"wheel_inertia", &BalbotParameters::wheel_inertia},
      {"gravity", &BalbotParameters::gravity},
      {"gear_ratio", &BalbotParameters::gear_ratio},
      {"torque_constant", &BalbotParameters::torque_constant},
      {"back_emf_constant", &BalbotParameters::back_emf_constant},
      {"armature_resistance", &BalbotParameters::armature_resistance},
      {"rotor_inertia", &BalbotParameters::rotor_inertia},
      {"motor_friction", &BalbotParameters::motor_friction},
      {"volts_per_input", &BalbotParameters::volts_per_input}};
  for (const auto& entry : node) {
    const auto key = entry.first.as<std::string>();
    const std::string where = "balbot: " + key;
    bool found = false;
    for (const auto& [name, member] : numbers) {
      if (key != name) continue;
      auto value = reader.number(entry.second, where);
      if (!value) return Failure{value.error()};
      robot.*member = value.value();
      found = true;
    }
    if (found) continue;
    if (key == "body_inertia") {
      auto value = reader.number(entry.second, where);
      if (!value) return Failure{value.error()};
      robot.body_inertia = value.value();
    } else if (key == "motors") {
      int value = 0;
      if (!entry.second.IsScalar() || !YAML::convert<int>::decode(entry.second, value)) {
        return reader.at(entry.second, where + ": expected a whole number");
      }
      robot.motors = value;
    } else {
      std::vector<std::string> known;
      for (const auto& [name, member] : numbers) known.emplace_back(name);
      known.insert(known.end(), {"body_inertia", "motors"});
      return reader.at(entry.first, "balbot: " + unknown_field(key, known));
    }
  }
  return robot;
}

std::string missing_matrix(const std::string& key, const char* what, bool regulator) {
  return "'" + key + "' is missing (" + what + "; '" + key + "d' is the same in discrete time)" +
         (regulator ? ", or give 'balbot'" : "");
}

std::string discrete_name(const std::string& given, const std::string& continuous) {
  return "'" + given + "' is discrete-time; with 'continuous: true' give '" + continuous + "'";
}

// The model: A and B (regulator) or A, G and C (filter), from matrices or from the robot's parameters.
Result<DesignSpec> read_model(const SpecReader& reader, const YAML::Node& root, DesignSpec spec) {
  const bool regulator = spec.kind == DesignKind::regulator;
  const std::string input = regulator ? "B" : "G";
  auto a_named = either(reader, root, "A");
  if (!a_named) return Failure{a_named.error()};
  auto b_named = either(reader, root, input);
  if (!b_named) return Failure{b_named.error()};
  if (regulator && root["balbot"]) {
    const YAML::Node balbot = root["balbot"];
    if (a_named.value() || b_named.value()) return reader.at(balbot, "'balbot' gives A and B: remove the other A or B");
    if (root["continuous"] && !spec.continuous) {
      return reader.at(root["continuous"], "the robot's model is continuous-time: remove 'continuous: false'");
    }
    auto robot = read_balbot(reader, balbot);
    if (!robot) return Failure{robot.error()};
    auto model = linearise_balbot(robot.value());
    if (!model) return reader.at(balbot, "balbot: " + model.error());
    spec.a = model.value().a;
    spec.b = model.value().b;
    spec.continuous = true;
    spec.model_place = reader.place(balbot);
    return spec;
  }
  const char* what_a = "the state matrix, n x n";
  const char* what_b = regulator ? "the input matrix, n x m" : "the noise input matrix, n x w";
  for (const auto& [named, key, what] :
       {std::tuple{&a_named.value(), std::string{"A"}, what_a}, std::tuple{&b_named.value(), input, what_b}}) {
    if (!*named) return reader.at(root, missing_matrix(key, what, regulator));
    if (spec.continuous && (*named)->key != key) return reader.at((*named)->node, discrete_name((*named)->key, key));
  }
  auto a = reader.matrix(a_named.value()->node, a_named.value()->key);
  if (!a) return Failure{a.error()};
  auto b = reader.matrix(b_named.value()->node, b_named.value()->key);
  if (!b) return Failure{b.error()};
  spec.a = std::move(a).value();
  spec.b = std::move(b).value();
  const Eigen::Index n = spec.a.rows();
  if (spec.a.cols() != n) {
    return reader.at(
        a_named.value()->node,
        a_named.value()->key + " must be square (a row and a column per state); it is " + size_text(spec.a));
  }
  if (spec.b.rows() != n) {
    return reader.at(b_named.value()->node, b_named.value()->key + " has " + std::to_string(spec.b.rows()) +
                                                " rows; A has " + std::to_string(n) + " (a row per state)");
  }
  spec.model_place = reader.place(b_named.value()->node);
  if (regulator) return spec;
  if (!root["C"]) return reader.at(root, "'C' is missing (the output matrix, p x n)");
  auto c = reader.matrix(root["C"], "C");
  if (!c) return Failure{c.error()};
  spec.c = std::move(c).value();
  if (spec.c.cols() != n) {
    return reader.at(root["C"], "C has " + std::to_string(spec.c.cols()) + " columns; A has " + std::to_string(n) +
                                    " (a column per state)");
  }
  spec.model_place = reader.place(root["C"]);
  return spec;
}

// Q and R: present, of the sizes the model asks for, and weights.
std::optional<Failure> read_weights(const SpecReader& reader, const YAML::Node& root, DesignSpec& spec) {
  const bool regulator = spec.kind == DesignKind::regulator;
  const Eigen::Index q_size = regulator ? spec.a.rows() : spec.b.cols();
  const Eigen::Index r_size = regulator ? spec.b.cols() : spec.c.rows();
  const std::string q_rule = regulator ? "a row and a column per state, like A" : "a row and a column per column of G";
  const std::string r_rule =
      regulator ? "a row and a column per input, a column of B" : "a row and a column per output, a row of C";
  for (const auto& [key, target, size, rule, definite] :
       {std::tuple{"Q", &spec.q, q_size, q_rule, false}, std::tuple{"R", &spec.r, r_size, r_rule, true}}) {
    const YAML::Node node = root[key];
    if (!node) {
      return reader.at(root, std::string{"'"} + key + "' is missing (" + std::to_string(size) + "x" +
                                 std::to_string(size) + ": " + rule + ")");
    }
    auto value = reader.matrix(node, key);
    if (!value) return Failure{value.error()};
    *target = std::move(value).value();
    if (target->rows() != size || target->cols() != size) {
      return reader.at(node, std::string{key} + " must be " + std::to_string(size) + "x" + std::to_string(size) + " (" +
                                 rule + "); it is " + size_text(*target));
    }
    if (auto problem = weight_problem(key, *target, definite)) return reader.at(node, *problem);
  }
  return std::nullopt;
}

std::optional<Failure> read_type(const SpecReader& reader, const YAML::Node& root, std::string& type);

Result<DesignSpec> read_spec(const SpecReader& reader, const YAML::Node& root, DesignKind kind) {
  const bool regulator = kind == DesignKind::regulator;
  const auto unknown =
      regulator
          ? reader.only(root, "", {"A", "B", "Ad", "Bd", "balbot", "continuous", "period_s", "Q", "R", "name", "type"})
          : reader.only(root, "", {"A", "C", "G", "Ad", "Gd", "continuous", "period_s", "Q", "R", "name", "type"});
  if (unknown) return *unknown;
  DesignSpec spec;
  spec.kind = kind;
  spec.name = regulator ? "K" : "L";
  if (const YAML::Node node = root["continuous"]) {
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, spec.continuous)) {
      return reader.at(node, "continuous: expected true or false");
    }
  }
  if (const YAML::Node node = root["period_s"]) {
    auto period = reader.number(node, "period_s");
    if (!period) return Failure{period.error()};
    if (period.value() <= 0) return reader.at(node, "period_s: the sample period must be more than 0 seconds");
    spec.period_s = period.value();
  }
  auto model = read_model(reader, root, std::move(spec));
  if (!model) return Failure{model.error()};
  spec = std::move(model).value();
  if (spec.continuous && !spec.period_s) {
    return reader.at(root, "a continuous-time model needs 'period_s', the sample period in seconds, to discretise it");
  }
  if (auto problem = read_weights(reader, root, spec)) return *problem;
  if (const YAML::Node node = root["name"]) {
    const std::string name = node.IsScalar() ? node.Scalar() : "";
    bool identifier = !name.empty() && std::isdigit(static_cast<unsigned char>(name[0])) == 0;
    for (const char letter : name)
      identifier = identifier && (std::isalnum(static_cast<unsigned char>(letter)) != 0 || letter == '_');
    if (!identifier) return reader.at(node, "name: expected a parameter name (letters, digits, _; not a digit first)");
    spec.name = name;
  }
  if (const YAML::Node node = root["type"]) {
    if (!node.IsScalar() || (node.Scalar() != "single" && node.Scalar() != "double")) {
      return reader.at(node, "type: expected single or double");
    }
    spec.type = node.Scalar();
  }
  return spec;
}

// The printed parameters' type.
std::optional<Failure> read_type(const SpecReader& reader, const YAML::Node& root, std::string& type) {
  if (const YAML::Node node = root["type"]) {
    if (!node.IsScalar() || (node.Scalar() != "single" && node.Scalar() != "double")) {
      return reader.at(node, "type: expected single or double");
    }
    type = node.Scalar();
  }
  return std::nullopt;
}

Result<PidDesignSpec> read_pid_spec(const SpecReader& reader, const YAML::Node& root) {
  if (auto unknown = reader.only(root, "",
                                 {"balbot", "period_s", "input_delay_s", "sensor_height_m", "kalman_Q", "kalman_R", "N",
                                  "minimum_damping", "maximum_high_frequency_gain", "type"})) {
    return *unknown;
  }
  PidDesignSpec spec;
  const YAML::Node balbot = root["balbot"];
  if (!balbot) return reader.at(root, "'balbot' is missing (the robot's parameters, or {} for the defaults)");
  auto robot = read_balbot(reader, balbot);
  if (!robot) return Failure{robot.error()};
  spec.loop.robot = robot.value();
  spec.model_place = reader.place(balbot);
  const std::pair<const char*, double*> numbers[] = {
      {"period_s", &spec.loop.period_s},
      {"input_delay_s", &spec.loop.input_delay_s},
      {"sensor_height_m", &spec.loop.sensor_height_m},
      {"kalman_Q", &spec.loop.kalman_q},
      {"N", &spec.criterion.n},
      {"minimum_damping", &spec.criterion.minimum_damping},
      {"maximum_high_frequency_gain", &spec.criterion.maximum_high_frequency_gain}};
  for (const auto& [key, target] : numbers) {
    if (!root[key]) continue;
    auto value = reader.number(root[key], key);
    if (!value) return Failure{value.error()};
    *target = value.value();
  }
  if (const YAML::Node node = root["kalman_R"]) {
    auto r = reader.matrix(node, "kalman_R");
    if (!r) return Failure{r.error()};
    if (r.value().rows() != 2 || r.value().cols() != 2) {
      return reader.at(node, "kalman_R must be 2x2 (the tilt's and the rate's noise); it is " + size_text(r.value()));
    }
    spec.loop.kalman_r = r.value();
  }
  if (spec.criterion.n <= 0) return reader.at(root["N"], "N: the derivative filter's coefficient must be above 0");
  if (auto problem = read_type(reader, root, spec.type)) return *problem;
  return spec;
}

// The file's text as a YAML map, read by `read`; YAML's own errors as "file:line:column: what".
template <typename Read>
auto parse_map(std::string_view text, const std::string& file, const std::string& expected, Read read)
    -> decltype(read(SpecReader{file}, YAML::Node{})) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string{text});
  } catch (const YAML::Exception& error) {
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ":" + std::to_string(error.mark.column + 1) +
                   ": not YAML: " + error.msg};
  }
  if (!root.IsMap()) return Failure{file + ": expected a map of " + expected + " (docs/CLI.md)"};
  try {
    return read(SpecReader{file}, root);
  } catch (const YAML::Exception& error) {  // a key that is not a scalar, and the like
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ": " + error.msg};
  }
}

}  // namespace

Result<DesignSpec> parse_design_spec(std::string_view text, const std::string& file, DesignKind kind) {
  const char* expected = kind == DesignKind::regulator ? "matrices: A, B, Q and R" : "matrices: A, C, G, Q and R";
  return parse_map(text, file, expected,
                   [kind](const SpecReader& reader, const YAML::Node& root) { return read_spec(reader, root, kind); });
}

Result<DesignSpec> load_design_spec(const std::string& path, DesignKind kind) {
  auto text = read_text_file(path);
  if (!text) return Failure{text.error()};
  return parse_design_spec(text.value(), path, kind);
}

Result<PidDesignSpec> parse_pid_design_spec(std::string_view text, const std::string& file) {
  return parse_map(text, file, "the robot's and the loop's parameters: balbot, period_s, ...", read_pid_spec);
}

Result<PidDesignSpec> load_pid_design_spec(const std::string& path) {
  auto text = read_text_file(path);
  if (!text) return Failure{text.error()};
  return parse_pid_design_spec(text.value(), path);
}

}  // namespace duet::control
