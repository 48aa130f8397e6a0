#pragma once
// Removes the files and directories an operation created if it does not finish, so a failed
// import leaves no half-written bag or trajectory behind that a later stage could mistake for a
// good one. Paths that existed before are never touched.
//
//   OutputGuard guard;
//   guard.Add(bag_path);
//   WriteBag(bag_path);   // throws: the destructor removes bag_path
//   guard.Commit();

#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

namespace littermap {

class OutputGuard {
 public:
  OutputGuard() = default;
  OutputGuard(const OutputGuard&) = delete;
  OutputGuard& operator=(const OutputGuard&) = delete;
  ~OutputGuard() {
    if (committed_) return;
    for (const auto& [path, existed] : outputs_) {
      std::error_code ignored;
      if (!existed) std::filesystem::remove_all(path, ignored);
    }
  }

  // Call before the operation creates `path`.
  void Add(const std::filesystem::path& path) {
    if (path.empty()) return;
    std::error_code ignored;
    outputs_.emplace_back(path, std::filesystem::exists(path, ignored));
  }
  void Commit() { committed_ = true; }

 private:
  std::vector<std::pair<std::filesystem::path, bool>> outputs_;
  bool committed_ = false;
};

}  // namespace littermap
