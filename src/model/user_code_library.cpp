#include "duet/model/user_code_library.hpp"

#include <dlfcn.h>
#include <stdlib.h>  // mkdtemp

#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "duet/support/compiler.hpp"
#include "user_code.hpp"

namespace duet::model {
namespace {

std::string entry_name(const ProgramBlock& block) { return "duet_code_" + block.identifier; }

// The source: the structures as generated code declares them, the users' headers, and one C entry per block.
std::string library_source(const Program& program) {
  std::string text = "// Written by duet sim: the Code blocks of " + program.model->name + ".\n";
  text += "#include <cstddef>\n#include <cstdint>\n\nnamespace duet_simulation {\n";
  std::set<std::string> headers;
  for (const ProgramBlock& block : program.blocks) {
    if (!block.block->code) continue;
    text += code_structures(program, block);
    headers.insert(block.block->code->file);
  }
  text += "}  // namespace duet_simulation\n\n";
  for (const std::string& header : headers) text += "#include \"" + header + "\"\n";
  text += "\nnamespace duet_simulation {\n";
  for (const ProgramBlock& block : program.blocks) {
    if (!block.block->code) continue;
    const std::string space = "code::" + block.identifier + "::";
    const CodeInterface interface = code_interface(program, block);
    const auto checks = [&](const std::string& structure, const std::vector<Field>& fields, std::size_t size) {
      for (const Field& field : fields) {
        text += "static_assert(offsetof(" + space + structure + ", " + field.name +
                ") == " + std::to_string(field.offset) + ");\n";
      }
      text += "static_assert(sizeof(" + space + structure + ") == " + std::to_string(size) + ");\n";
    };
    checks("Inputs", interface.inputs, interface.inputs_size);
    checks("Outputs", interface.outputs, interface.outputs_size);
    checks("State", interface.state, interface.state_size);
    checks("Parameters", interface.parameters, interface.parameters_size);
    text += "extern \"C\" void " + entry_name(block) +
            "(const void* in, void* out, void* state, const void* parameters) {\n  " + block.block->code->function +
            "(*static_cast<const " + space + "Inputs*>(in), *static_cast<" + space + "Outputs*>(out), *static_cast<" +
            space + "State*>(state), *static_cast<const " + space + "Parameters*>(parameters));\n}\n";
  }
  return text + "}  // namespace duet_simulation\n";
}

}  // namespace

Result<std::unique_ptr<UserCodeLibrary>> UserCodeLibrary::build(const Program& program) {
  std::unique_ptr<UserCodeLibrary> library{new UserCodeLibrary};
  bool any = false;
  for (const ProgramBlock& block : program.blocks) any = any || block.block->code.has_value();
  if (!any) return library;
  std::string pattern = (std::filesystem::temp_directory_path() / "duet_sim_XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) return Failure{"cannot make a temporary folder for the Code blocks"};
  library->folder_ = pattern;
  const std::filesystem::path source = library->folder_ / "user_code.cpp";
  const std::filesystem::path shared = library->folder_ / "user_code.so";
  std::ofstream{source} << library_source(program);
  const std::filesystem::path model_folder =
      std::filesystem::absolute(std::filesystem::path{program.model->file}).parent_path();
  std::vector<std::string> command{cxx_compiler(),
                                   "-std=c++20",
                                   "-O2",
                                   "-ffp-contract=off",  // as duet_blocks: the firmware's rounding
                                   "-fPIC",
                                   "-shared",
                                   "-I" + model_folder.string(),
                                   "-I" DUET_BLOCKS_INCLUDE_DIR,
                                   "-o",
                                   shared.string(),
                                   source.string()};
  if (auto compiled = compile(std::move(command), library->folder_ / "messages.txt", "the Code blocks"); !compiled) {
    return Failure{compiled.error()};
  }
  library->handle_ = dlopen(shared.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library->handle_ == nullptr) return Failure{std::string{"cannot load the Code blocks: "} + dlerror()};
  for (std::size_t index = 0; index < program.blocks.size(); ++index) {
    const ProgramBlock& block = program.blocks[index];
    if (!block.block->code) continue;
    void* symbol = dlsym(library->handle_, entry_name(block).c_str());
    if (symbol == nullptr) return Failure{"the Code blocks' library lacks " + entry_name(block)};
    library->functions_[index] = reinterpret_cast<CodeFunction>(symbol);
  }
  return library;
}

UserCodeLibrary::~UserCodeLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
  std::error_code ignored;
  if (!folder_.empty()) std::filesystem::remove_all(folder_, ignored);
}

CodeFunction UserCodeLibrary::function(std::size_t block) const {
  const auto found = functions_.find(block);
  return found == functions_.end() ? nullptr : found->second;
}

}  // namespace duet::model
