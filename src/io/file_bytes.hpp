// Whole-file reading and all-or-nothing writing (a file is written under a
// temporary name and renamed, so no partial file is ever left behind).
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace partet {

// The bytes of `path`; InputError naming the file if it cannot be read or is empty.
std::string read_file_bytes(const std::string& path);

// Writes `bytes` to `path` atomically; InputError naming the file on failure.
void write_file_atomic(const std::string& path, std::string_view bytes);

// A file written in pieces under a temporary name (`path` + ".partial") and
// renamed to `path` by commit(); destroyed uncommitted (an error on the
// way), it removes the temporary file. InputError naming the file on
// failure.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();
  void write(std::string_view bytes);
  void commit();

 private:
  void fail(int err);

  std::string path_, tmp_;
  std::FILE* file_ = nullptr;
};

// Lower-case extension without the dot ("stl" for "a/b.STL"); empty if none.
std::string file_extension(const std::string& path);

// The file name without its directories ("b.stl" for "a/b.stl").
std::string file_basename(const std::string& path);

}  // namespace partet
