#include "cli/command_names.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace littermap::cli {
namespace {

// Levenshtein distance: insertions, deletions and substitutions.
std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

void CheckCommandNames(CLI::App& app, int argc, const char* const* argv) {
  CLI::App* command = &app;
  std::string path;  // the words of the command so far, "eval "
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word.front() == '-') continue;  // -q, --help, --version take no value
    const std::vector<CLI::App*> subcommands =
        command->get_subcommands([](const CLI::App*) { return true; });
    if (subcommands.empty()) return;
    CLI::App* named = nullptr;
    const CLI::App* closest = nullptr;
    std::size_t closest_distance = 0;
    for (CLI::App* subcommand : subcommands) {
      if (subcommand->check_name(word)) named = subcommand;
      const std::size_t distance = EditDistance(word, subcommand->get_name());
      if (closest == nullptr || distance < closest_distance) {
        closest = subcommand;
        closest_distance = distance;
      }
    }
    if (named != nullptr) {
      command = named;
      path += word + " ";
      continue;
    }
    std::string message = "unknown command '" + path + word + "'";
    if (closest != nullptr && closest_distance <= std::max<std::size_t>(2, word.size() / 3)) {
      message += " (did you mean '" + path + closest->get_name() + "'?)";
    }
    throw UsageError(message + "; 'littermap " + path + "--help' lists the commands");
  }
}

}  // namespace littermap::cli
