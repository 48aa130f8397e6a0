// The modules stack in one order: a module includes and links only the modules below it, and no
// library but the command line's links the simulator, the drivers or the importers. The order is
// the README's module map; a new module has to take its place in it here.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace littermap {
namespace {

// Lowest first. The sources of a run (importers, live drivers, the simulator) sit above the
// stages that read runs, which see only the bag module: only the command line puts them together.
const std::vector<std::string> kOrder = {"core",      "bag",     "eval",    "db",   "reconstruct",
                                         "detect",    "run",     "heatmap", "site", "reports",
                                         "importers", "capture", "sim",     "cli"};

std::size_t Rank(const std::string& module) {
  const auto it = std::find(kOrder.begin(), kOrder.end(), module);
  return static_cast<std::size_t>(it - kOrder.begin());
}

// module -> the littermap modules it links directly, as CMake resolved the targets.
std::map<std::string, std::set<std::string>> ReadModuleLinks() {
  std::ifstream in(LITTERMAP_MODULE_LINKS);
  std::map<std::string, std::set<std::string>> links;
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::istringstream deps(line.substr(colon + 1));
    std::set<std::string>& out = links[line.substr(0, colon)];
    for (std::string dep; deps >> dep;) out.insert(dep);
  }
  return links;
}

std::set<std::string> Reachable(const std::map<std::string, std::set<std::string>>& links,
                                const std::string& module) {
  std::set<std::string> seen;
  std::vector<std::string> todo = {module};
  while (!todo.empty()) {
    const std::string next = todo.back();
    todo.pop_back();
    const auto it = links.find(next);
    if (it == links.end()) continue;
    for (const std::string& dep : it->second) {
      if (seen.insert(dep).second) todo.push_back(dep);
    }
  }
  return seen;
}

TEST(ModuleOrder, EveryModuleHasItsPlace) {
  const auto links = ReadModuleLinks();
  ASSERT_GE(links.size(), 10u) << "cannot read " << LITTERMAP_MODULE_LINKS;
  for (const auto& [module, deps] : links) {
    EXPECT_LT(Rank(module), kOrder.size()) << module << " is not in the module order";
  }
  for (const std::string& module : kOrder) {
    EXPECT_TRUE(links.contains(module)) << module << " is in the order but not built";
  }
}

TEST(ModuleOrder, LinksGoDownOnly) {
  for (const auto& [module, deps] : ReadModuleLinks()) {
    for (const std::string& dep : deps) {
      EXPECT_LT(Rank(dep), Rank(module)) << module << " links " << dep << ", which is above it";
    }
  }
}

TEST(ModuleOrder, IncludesGoDownOnly) {
  const std::regex include(R"re(^\s*#\s*include\s*"([a-z_]+)/[^"]+")re");
  std::size_t files = 0;
  for (const std::string& module : kOrder) {
    const std::filesystem::path dir = std::filesystem::path(LITTERMAP_SOURCE_DIR) / module;
    ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".hpp") continue;
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        std::smatch match;
        if (!std::regex_search(line, match, include)) continue;
        const std::string used = match[1];
        if (used == module || Rank(used) == kOrder.size()) continue;  // not a module
        EXPECT_LT(Rank(used), Rank(module))
            << entry.path().string() << ":" << number << " includes " << used << ", which is above "
            << module;
      }
    }
  }
  EXPECT_GT(files, 300u);
}

TEST(ModuleOrder, OnlyTheCommandLineLinksTheSimulatorAndTheDrivers) {
  const auto links = ReadModuleLinks();
  for (const auto& [module, deps] : links) {
    if (module == "cli") continue;
    const std::set<std::string> reached = Reachable(links, module);
    for (const char* upper : {"sim", "capture", "importers"}) {
      EXPECT_FALSE(reached.contains(upper)) << module << " links " << upper;
    }
  }
  // The stages read runs through the bag module alone.
  for (const char* stage : {"reconstruct", "detect", "run"}) {
    EXPECT_TRUE(Reachable(links, stage).contains("bag")) << stage;
  }
}

}  // namespace
}  // namespace littermap
