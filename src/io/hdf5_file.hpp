// A small RAII wrapper over the HDF5 C API: just what the trajectory and checkpoint
// writers need. Every failure becomes a cortex::RunError naming file and object
// (InputError when an existing file cannot be opened), never an HDF5 stack dump.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cortex::h5 {

using Shape = std::vector<hsize_t>;  // dataset dimensions, slowest-varying first

class File {
 public:
  // A file built in memory (HDF5's core driver, no backing file): nothing touches the disk
  // until its image() is written out, e.g. with writeFileAtomically, so a full disk or a
  // crash can never leave it half-written. `name` is for messages. (Bytes prepended to
  // the image form a user block: HDF5 finds its superblock after them.)
  static File createInMemory(const std::filesystem::path& name);
  static File openReadWrite(const std::filesystem::path& path);
  static File openReadOnly(const std::filesystem::path& path);

  File(File&& other) noexcept;
  File& operator=(File&&) = delete;  // not needed; a File lives for one block of work
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  ~File();

  const std::filesystem::path& path() const { return path_; }

  // Object paths are absolute ("/snapshots/000001/membranes/cell").
  bool exists(const std::string& objpath) const;
  void createGroups(const std::string& objpath);  // like mkdir -p
  void remove(const std::string& objpath);        // unlinks a group or dataset
  std::vector<std::string> children(const std::string& group_path) const;  // sorted

  // Datasets: `shape` must multiply to data.size(); empty shape means 1-D.
  // Missing parent groups are created; an existing dataset is replaced.
  void write(const std::string& path, const std::vector<double>& data, Shape shape = {});
  void write(const std::string& path, const std::vector<std::int32_t>& data, Shape shape = {});
  void write(const std::string& path, const std::vector<std::int64_t>& data, Shape shape = {});
  void write(const std::string& path, const std::vector<std::int8_t>& data, Shape shape = {});
  void write(const std::string& path, const std::vector<std::uint8_t>& data, Shape shape = {});
  // A 1-D dataset of variable-length UTF-8 strings (h5py reads them as str).
  void write(const std::string& path, const std::vector<std::string>& data);

  // Reads convert from the stored numeric type; `shape` (if given) receives the dims.
  std::vector<double> readDoubles(const std::string& path, Shape* shape = nullptr) const;
  std::vector<std::int32_t> readInt32(const std::string& path, Shape* shape = nullptr) const;
  std::vector<std::int64_t> readInt64(const std::string& path, Shape* shape = nullptr) const;
  std::vector<std::int8_t> readInt8(const std::string& path, Shape* shape = nullptr) const;
  std::vector<std::uint8_t> readUInt8(const std::string& path, Shape* shape = nullptr) const;
  std::vector<std::string> readStrings(const std::string& path) const;
  Shape shape(const std::string& path) const;  // without reading the data

  // Scalar attributes on any group or dataset; setting replaces an existing one.
  void setAttribute(const std::string& objpath, const std::string& name, double value);
  void setAttribute(const std::string& objpath, const std::string& name, std::int64_t value);
  void setAttribute(const std::string& objpath, const std::string& name, const std::string& value);
  // A one-dimensional integer array attribute (e.g. a grid shape).
  void setAttribute(const std::string& objpath, const std::string& name, const std::vector<std::int64_t>& values);
  bool attributeExists(const std::string& objpath, const std::string& name) const;
  double attributeDouble(const std::string& objpath, const std::string& name) const;
  std::int64_t attributeInt64(const std::string& objpath, const std::string& name) const;
  std::string attributeString(const std::string& objpath, const std::string& name) const;

  // An external link at `objpath` to object `target` of HDF5 file `file` (a path relative
  // to this file's folder, where HDF5 looks for it when the link is followed).
  void linkExternal(const std::string& objpath, const std::string& file, const std::string& target);

  void flush();
  // The bytes of an in-memory file (flushed first).
  std::string image();

 private:
  File(hid_t id, std::filesystem::path path) : id_(id), path_(std::move(path)) {}
  template <class T>
  void writeAs(const std::string& path, const std::vector<T>& data, Shape shape);
  template <class T>
  std::vector<T> readAs(const std::string& path, Shape* shape) const;
  // `count` < 0 writes a scalar, otherwise a one-dimensional array of `count` values.
  void setAttributeRaw(const std::string& objpath, const std::string& name, hid_t type,
                       const void* value, hssize_t count = -1);
  void readAttributeRaw(const std::string& objpath, const std::string& name, hid_t mem_type,
                        void* value) const;
  [[noreturn]] void fail(const std::string& what, const std::string& objpath) const;

  hid_t id_ = H5I_INVALID_HID;
  std::filesystem::path path_;
};

}  // namespace cortex::h5
