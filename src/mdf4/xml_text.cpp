#include "xml_text.hpp"

#include <array>
#include <utility>

namespace duet::mdf4 {
namespace {

std::string resolve_entities(std::string_view text) {
  constexpr std::array<std::pair<std::string_view, char>, 5> entities{
      {{"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&quot;", '"'}, {"&apos;", '\''}}};
  std::string resolved;
  for (std::size_t at = 0; at < text.size();) {
    bool replaced = false;
    for (const auto& [entity, character] : entities) {
      if (text.substr(at, entity.size()) == entity) {
        resolved += character;
        at += entity.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) resolved += text[at++];
  }
  return resolved;
}

}  // namespace

std::string element_text(std::string_view xml, std::string_view name) {
  const std::string open = "<" + std::string{name};
  for (std::size_t at = xml.find(open); at != std::string_view::npos; at = xml.find(open, at + 1)) {
    const std::size_t after = at + open.size();
    if (after >= xml.size() || (xml[after] != '>' && xml[after] != ' ' && xml[after] != '/')) continue;
    const std::size_t content = xml.find('>', after);
    if (content == std::string_view::npos || xml[content - 1] == '/') return {};
    const std::size_t close = xml.find("</" + std::string{name} + ">", content);
    if (close == std::string_view::npos) return {};
    return resolve_entities(xml.substr(content + 1, close - content - 1));
  }
  return {};
}

std::string text_of_xml(std::string_view xml) {
  if (xml.find("<TX") == std::string_view::npos) return std::string{xml};
  return element_text(xml, "TX");
}

}  // namespace duet::mdf4
