#pragma once
// Removes the files and directories an operation created if it does not finish, so a failed
// import leaves no half-written bag or trajectory behind that a later stage could mistake for a
// good one. A path that existed before is never removed: an empty directory (a bag writer
// accepts one) is emptied again, anything else is not touched.
//
//   OutputGuard guard;
//   guard.Add(bag_path);
//   WriteBag(bag_path);   // throws: the destructor removes bag_path
//   guard.Commit();

#include <filesystem>
#include <system_error>
#include <vector>

namespace littermap::bag {

class OutputGuard {
 public:
  OutputGuard() = default;
  OutputGuard(const OutputGuard&) = delete;
  OutputGuard& operator=(const OutputGuard&) = delete;
  ~OutputGuard() {
    if (committed_) return;
    for (const Output& output : outputs_) {
      std::error_code ignored;
      switch (output.before) {
        case Before::kAbsent:
          std::filesystem::remove_all(output.path, ignored);
          break;
        case Before::kEmptyDirectory:
          for (const auto& entry : std::filesystem::directory_iterator(output.path, ignored)) {
            std::filesystem::remove_all(entry.path(), ignored);
          }
          break;
        case Before::kOther:
          break;
      }
    }
  }

  // Call before the operation creates `path`.
  void Add(const std::filesystem::path& path) {
    if (path.empty()) return;
    std::error_code error;
    Before before = Before::kOther;
    if (!std::filesystem::exists(path, error)) {
      before = Before::kAbsent;
    } else if (std::filesystem::is_directory(path, error) &&
               std::filesystem::is_empty(path, error) && !error) {
      before = Before::kEmptyDirectory;
    }
    outputs_.push_back({path, before});
  }
  void Commit() { committed_ = true; }

 private:
  enum class Before { kAbsent, kEmptyDirectory, kOther };
  struct Output {
    std::filesystem::path path;
    Before before = Before::kOther;
  };
  std::vector<Output> outputs_;
  bool committed_ = false;
};

}  // namespace littermap::bag
