// Writing a file atomically: write to `path + ".part"`, then commit() renames it to `path`.
// Until commit() the final name is never touched; destroying an uncommitted PartFile deletes
// the .part file, so a failure leaves nothing behind.
#pragma once
#include <string>

namespace impulse::render {

class PartFile {
 public:
  explicit PartFile(std::string final_path);
  ~PartFile();
  PartFile(const PartFile&) = delete;
  PartFile& operator=(const PartFile&) = delete;

  const std::string& final_path() const { return final_path_; }
  const std::string& part_path() const { return part_path_; }
  bool committed() const { return committed_; }

  void commit();  // renames .part to the final path; throws std::runtime_error naming both

 private:
  std::string final_path_;
  std::string part_path_;
  bool committed_ = false;
};

}  // namespace impulse::render
