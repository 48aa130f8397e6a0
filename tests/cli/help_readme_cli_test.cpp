// The README and `--help` tell the same story: every option a command takes is documented in
// the README's section on that command, and the options a section's heading shows exist.

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

// The lines of a --help text's section ("Options:", "Subcommands:") up to the next blank line.
std::vector<std::string> HelpSection(const std::string& help, const std::string& title) {
  std::vector<std::string> lines;
  std::istringstream in(help);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line == title) {
      inside = true;
    } else if (inside && line.empty()) {
      break;
    } else if (inside) {
      lines.push_back(line);
    }
  }
  return lines;
}

// A command's options, each as its names ("-o", "--output"), without --help and --quiet.
std::vector<std::vector<std::string>> OptionsOf(const std::string& help) {
  std::vector<std::vector<std::string>> options;
  static const std::regex name(R"((^|,)(--?[a-z][a-z-]*))");
  for (const std::string& line : HelpSection(help, "Options:")) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || line[start] != '-') continue;  // a description line
    const std::string names = line.substr(start, line.find(' ', start) - start);
    std::vector<std::string> aliases;
    for (std::sregex_iterator it(names.begin(), names.end(), name), end; it != end; ++it) {
      aliases.push_back((*it)[2]);
    }
    if (aliases.back() == "--help" || aliases.back() == "--quiet") continue;
    options.push_back(aliases);
  }
  return options;
}

std::string Help(const std::string& command) {
  return test::RunLittermap(command + " --help").output;
}

// Every leaf command ("info", "eval map", "site init").
void LeafCommands(const std::string& command, std::vector<std::string>* leaves) {
  const std::vector<std::string> subcommands = HelpSection(Help(command), "Subcommands:");
  if (subcommands.empty()) {
    leaves->push_back(command);
    return;
  }
  for (const std::string& line : subcommands) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    LeafCommands(command.empty() ? name : command + " " + name, leaves);
  }
}

struct ReadmeSection {
  std::string heading;
  std::string text;
};

std::vector<ReadmeSection> ReadmeSections() {
  std::vector<ReadmeSection> sections;
  std::istringstream in(test::Slurp(std::filesystem::path(LITTERMAP_SOURCE_DIR) / "README.md"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.starts_with("## ") || line.starts_with("### ")) sections.push_back({line, ""});
    if (!sections.empty()) sections.back().text += line + "\n";
  }
  return sections;
}

// A section is a command's when its heading shows `littermap COMMAND ...` or `COMMAND`.
bool SectionOf(const ReadmeSection& section, const std::string& command) {
  return section.heading.starts_with("### ") &&
         (section.heading.find("`littermap " + command + " ") != std::string::npos ||
          section.heading.find("`littermap " + command + "`") != std::string::npos ||
          section.heading.find("`" + command + "`") != std::string::npos);
}

bool Mentions(const std::string& text, const std::string& option) {
  static const std::string kAfter = " `[]|.,;:)=\n";
  for (std::size_t at = text.find(option); at != std::string::npos;
       at = text.find(option, at + 1)) {
    const std::size_t end = at + option.size();
    if (end == text.size() || kAfter.find(text[end]) != std::string::npos) return true;
  }
  return false;
}

TEST(HelpReadmeCli, EveryOptionOfEveryCommandIsInItsReadmeSection) {
  std::vector<std::string> commands;
  LeafCommands("", &commands);
  ASSERT_GE(commands.size(), 20u) << "the command list was not read from --help";
  const std::vector<ReadmeSection> sections = ReadmeSections();
  std::map<std::string, std::set<std::string>> options_of_section;  // heading -> all options
  for (const std::string& command : commands) {
    std::string text;
    std::vector<std::string> headings;
    for (const ReadmeSection& section : sections) {
      if (!SectionOf(section, command)) continue;
      text += section.text;
      headings.push_back(section.heading);
    }
    ASSERT_FALSE(headings.empty()) << "no README section for `littermap " << command << "`";
    for (const std::vector<std::string>& aliases : OptionsOf(Help(command))) {
      bool documented = false;
      for (const std::string& alias : aliases) documented = documented || Mentions(text, alias);
      EXPECT_TRUE(documented) << "`littermap " << command << " " << aliases.back()
                              << "` is not in the README's section " << headings.front();
      for (const std::string& heading : headings) {
        options_of_section[heading].insert(aliases.begin(), aliases.end());
      }
    }
  }
  static const std::regex option(R"(--[a-z][a-z-]*)");
  for (const auto& [heading, options] : options_of_section) {
    for (std::sregex_iterator it(heading.begin(), heading.end(), option), end; it != end; ++it) {
      EXPECT_TRUE(options.count(it->str()))
          << heading << " shows " << it->str() << ", which none of its commands takes";
    }
  }
}

}  // namespace
}  // namespace littermap
