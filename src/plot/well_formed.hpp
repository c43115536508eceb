#pragma once
// For tests: a small check that a document is well-formed XML, enough for the SVG written here. Elements nest and
// close, there is one root, attribute values are quoted and unique, and no text holds a bare '<' or an '&' that does
// not start an entity. No DTDs or CDATA sections: the writer never produces them.

#include <cctype>
#include <cstddef>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace duet::plot {

class WellFormed {
 public:
  explicit WellFormed(std::string_view xml) : xml_(xml) {}

  // "" if well-formed, else what is wrong and where.
  std::string problem() {
    std::vector<std::string_view> open;
    bool had_root = false;
    while (at_ < xml_.size()) {
      const char c = xml_[at_];
      if (c == '<' && xml_.substr(at_).starts_with("<?")) {
        if (!skip_past("?>")) return fail("unterminated <?");
      } else if (c == '<' && xml_.substr(at_).starts_with("<!--")) {
        if (!skip_past("-->")) return fail("unterminated comment");
      } else if (c == '<' && xml_.substr(at_).starts_with("</")) {
        at_ += 2;
        const std::string_view name = read_name();
        skip_spaces();
        if (at_ >= xml_.size() || xml_[at_] != '>') return fail("bad end tag");
        if (open.empty() || open.back() != name) return fail("end tag </" + std::string{name} + "> does not match");
        open.pop_back();
        ++at_;
      } else if (c == '<') {
        if (open.empty() && had_root) return fail("a second root element");
        had_root = true;
        ++at_;
        const std::string_view name = read_name();
        if (name.empty()) return fail("'<' without an element name");
        bool closed = false;
        if (std::string attributes = read_attributes(closed); !attributes.empty()) return fail(attributes);
        if (!closed) open.push_back(name);
      } else if (c == '&') {
        if (!entity()) return fail("'&' outside an entity");
      } else {
        if (open.empty() && !std::isspace(static_cast<unsigned char>(c))) return fail("text outside the root");
        ++at_;
      }
    }
    if (!open.empty()) return fail("<" + std::string{open.back()} + "> never closed");
    return had_root ? "" : fail("no root element");
  }

 private:
  [[nodiscard]] std::string fail(const std::string& what) const {
    return "offset " + std::to_string(at_) + ": " + what;
  }

  bool skip_past(std::string_view end) {
    const std::size_t found = xml_.find(end, at_);
    if (found == std::string_view::npos) return false;
    at_ = found + end.size();
    return true;
  }

  void skip_spaces() {
    while (at_ < xml_.size() && std::isspace(static_cast<unsigned char>(xml_[at_]))) ++at_;
  }

  std::string_view read_name() {
    const std::size_t start = at_;
    const auto name_char = [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' || c == '.';
    };
    while (at_ < xml_.size() && name_char(xml_[at_])) ++at_;
    return xml_.substr(start, at_ - start);
  }

  // At '&': an entity of XML's five or a character reference; moves past it.
  bool entity() {
    const std::size_t semicolon = xml_.find(';', at_);
    if (semicolon == std::string_view::npos) return false;
    const std::string_view name = xml_.substr(at_ + 1, semicolon - at_ - 1);
    bool known = name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos";
    if (name.size() > 1 && name[0] == '#') {
      known = name.substr(1).find_first_not_of(name[1] == 'x' ? "x0123456789abcdefABCDEF" : "0123456789") ==
              std::string_view::npos;
    }
    at_ = semicolon + 1;
    return known;
  }

  std::string read_attributes(bool& closed) {
    std::set<std::string_view> seen;
    for (;;) {
      skip_spaces();
      if (at_ >= xml_.size()) return "unterminated start tag";
      if (xml_.substr(at_).starts_with("/>")) {
        at_ += 2;
        closed = true;
        return "";
      }
      if (xml_[at_] == '>') {
        ++at_;
        return "";
      }
      const std::string_view name = read_name();
      if (name.empty()) return "bad attribute at offset " + std::to_string(at_);
      if (!seen.insert(name).second) return "attribute " + std::string{name} + " twice";
      skip_spaces();
      if (at_ >= xml_.size() || xml_[at_] != '=') return "attribute " + std::string{name} + " without '='";
      ++at_;
      skip_spaces();
      if (at_ >= xml_.size() || (xml_[at_] != '"' && xml_[at_] != '\'')) return "unquoted attribute value";
      const char quote = xml_[at_++];
      while (at_ < xml_.size() && xml_[at_] != quote) {
        if (xml_[at_] == '<') return "'<' in an attribute value";
        if (xml_[at_] == '&') {
          if (!entity()) return "'&' outside an entity in an attribute value";
        } else {
          ++at_;
        }
      }
      if (at_ >= xml_.size()) return "unterminated attribute value";
      ++at_;
    }
  }

  std::string_view xml_;
  std::size_t at_ = 0;
};

}  // namespace duet::plot
