#include "render/part_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace impulse::render {

PartFile::PartFile(std::string final_path) : final_path_(std::move(final_path)), part_path_(final_path_ + ".part") {}

PartFile::~PartFile() {
  if (!committed_) std::remove(part_path_.c_str());
}

void PartFile::commit() {
  if (std::rename(part_path_.c_str(), final_path_.c_str()) != 0) {
    throw std::runtime_error("cannot rename " + part_path_ + " to " + final_path_ + ": " + std::strerror(errno));
  }
  committed_ = true;
}

}  // namespace impulse::render
