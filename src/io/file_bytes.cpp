// Whole-file reads with clear errors, and atomic writes via rename.
#include "io/file_bytes.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace partet {

std::string read_file_bytes(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open: " + std::strerror(errno));
  std::string bytes;
  in.seekg(0, std::ios::end);
  std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path + ": cannot read: " + std::strerror(errno));
  bytes.resize(static_cast<size_t>(size));
  in.seekg(0, std::ios::beg);
  in.read(bytes.data(), size);
  if (!in) throw InputError(path + ": cannot read: " + std::strerror(errno));
  if (bytes.empty()) throw InputError(path + ": empty file");
  return bytes;
}

void write_file_atomic(const std::string& path, std::string_view bytes) {
  AtomicFile file(path);
  file.write(bytes);
  file.commit();
}

AtomicFile::AtomicFile(const std::string& path) : path_(path), tmp_(path + ".partial") {
  file_ = std::fopen(tmp_.c_str(), "wb");
  if (!file_) throw InputError(path_ + ": cannot write: " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (!file_) return;
  std::fclose(file_);
  std::remove(tmp_.c_str());
}

void AtomicFile::fail(int err) {
  std::fclose(file_);
  file_ = nullptr;
  std::remove(tmp_.c_str());
  throw InputError(path_ + ": cannot write: " + std::strerror(err));
}

void AtomicFile::write(std::string_view bytes) {
  PARTET_ASSERT(file_, "writing a committed file");
  if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail(errno);
}

void AtomicFile::commit() {
  PARTET_ASSERT(file_, "committing a file twice");
  if (std::fflush(file_) != 0) fail(errno);
  const int closed = std::fclose(file_);
  file_ = nullptr;
  if (closed != 0 || std::rename(tmp_.c_str(), path_.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp_.c_str());
    throw InputError(path_ + ": cannot write: " + std::strerror(err));
  }
}

std::string file_extension(const std::string& path) {
  std::string base = file_basename(path);
  size_t dot = base.rfind('.');
  if (dot == std::string::npos || dot == 0) return {};
  std::string ext = base.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string file_basename(const std::string& path) {
  size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace partet
