#include "command_line.hpp"

namespace balbot::pil {
namespace {

// The next word of `text`, which loses it and the spaces before it.
std::string_view next_word(std::string_view& text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  std::size_t length = 0;
  while (length < text.size() && text[length] != ' ') ++length;
  const std::string_view word = text.substr(0, length);
  text.remove_prefix(length);
  return word;
}

// "12", "0.5", "2.125" -> milliseconds; false for anything else, and for 0 or more than a year.
bool parse_seconds(std::string_view word, std::uint64_t& milliseconds) {
  std::uint64_t whole = 0;
  std::uint64_t thousandths = 0;
  std::size_t at = 0;
  std::size_t digits = 0;
  for (; at < word.size() && word[at] >= '0' && word[at] <= '9' && digits < 9; ++at, ++digits) {
    whole = whole * 10U + static_cast<std::uint64_t>(word[at] - '0');
  }
  if (digits == 0) return false;
  if (at < word.size() && word[at] == '.') {
    ++at;
    for (std::uint64_t scale = 100; scale > 0 && at < word.size() && word[at] >= '0' && word[at] <= '9'; scale /= 10) {
      thousandths += scale * static_cast<std::uint64_t>(word[at++] - '0');
    }
  }
  milliseconds = whole * 1000U + thousandths;
  constexpr std::uint64_t year_ms = 366ULL * 24U * 3600U * 1000U;
  return at == word.size() && milliseconds != 0 && milliseconds <= year_ms;
}

constexpr std::string_view usage = " (usage: --link DIRECTORY [--duration SECONDS])";

// DIRECTORY/to_plant and DIRECTORY/from_plant, NUL-terminated.
char pipe_paths[2][200];

std::string_view pipe_path(char (&path)[200], std::string_view directory, std::string_view name) {
  duet::TextBuffer<200> text;
  text.append(directory).append('/').append(name);
  const std::string_view joined = text.view();
  if (joined.size() + 1 > sizeof path) return {};
  joined.copy(path, joined.size());
  path[joined.size()] = '\0';
  return {path, joined.size()};
}

}  // namespace

CommandLine parse_command_line(std::string_view text) {
  CommandLine arguments;
  next_word(text);  // the program's name
  for (std::string_view word = next_word(text); !word.empty(); word = next_word(text)) {
    if (word == "--link") {
      const std::string_view directory = next_word(text);
      arguments.to_plant = pipe_path(pipe_paths[0], directory, "to_plant");
      arguments.from_plant = pipe_path(pipe_paths[1], directory, "from_plant");
      if (directory.empty() || arguments.to_plant.empty() || arguments.from_plant.empty()) {
        arguments.problem.append("--link needs a directory of at most 180 characters").append(usage);
        return arguments;
      }
      continue;
    }
    if (word != "--duration") {
      arguments.problem.append("unknown argument '").append(word).append("'").append(usage);
      return arguments;
    }
    const std::string_view value = next_word(text);
    if (!parse_seconds(value, arguments.duration_ms)) {
      arguments.problem.append("--duration needs seconds above 0 with at most 3 decimals, not '")
          .append(value)
          .append("'");
      return arguments;
    }
  }
  if (arguments.to_plant.empty()) arguments.problem.append("no --link").append(usage);
  return arguments;
}

}  // namespace balbot::pil
