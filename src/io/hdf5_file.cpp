#include "io/hdf5_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <type_traits>
#include <utility>

#include "core/error.hpp"

namespace cortex::h5 {
namespace {

// Owns one HDF5 identifier; each kind of object (group, dataset, ...) has its own close call.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { if (id_ >= 0) close_(id_); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// HDF5 prints its whole error stack to stderr by default; we report through exceptions instead.
void silenceHdf5Errors() {
  [[maybe_unused]] static const herr_t once = H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

// Link-creation properties that make H5Gcreate/H5Dcreate create missing parent groups.
hid_t intermediateGroupsLcpl() {
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  return lcpl;
}

// A variable-length UTF-8 string type: h5py reads it back as str.
hid_t utf8StringType() {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  return type;
}

// Stored type (explicitly little-endian, as h5py and numpy expect) and in-memory type of T.
template <class T>
std::pair<hid_t, hid_t> fileAndMemoryTypes() {
  if constexpr (std::is_same_v<T, double>) return {H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE};
  if constexpr (std::is_same_v<T, std::int32_t>) return {H5T_STD_I32LE, H5T_NATIVE_INT32};
  if constexpr (std::is_same_v<T, std::int64_t>) return {H5T_STD_I64LE, H5T_NATIVE_INT64};
  if constexpr (std::is_same_v<T, std::int8_t>) return {H5T_STD_I8LE, H5T_NATIVE_INT8};
  if constexpr (std::is_same_v<T, std::uint8_t>) return {H5T_STD_U8LE, H5T_NATIVE_UINT8};
}

hsize_t elementCount(const Shape& shape) {
  return std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<>());
}

Shape dimensions(hid_t dataset) {
  const Handle space(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  Shape dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

hid_t openExisting(const std::filesystem::path& path, unsigned flags, const char* mode) {
  silenceHdf5Errors();
  const hid_t id = H5Fopen(path.c_str(), flags, H5P_DEFAULT);
  if (id < 0) {
    throw InputError(fmt::format("cannot open HDF5 file '{}' for {} (missing, unreadable or "
                                 "not HDF5)", path.string(), mode));
  }
  return id;
}

}  // namespace

File File::createInMemory(const std::filesystem::path& name) {
  silenceHdf5Errors();
  const Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  // Grow the image 1 MiB at a time; never write a backing file.
  if (H5Pset_fapl_core(fapl.get(), 1 << 20, 0) < 0)
    throw RunError(fmt::format("cannot set up the in-memory HDF5 file '{}'", name.string()));
  const hid_t id = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get());
  if (id < 0) throw RunError(fmt::format("cannot create the in-memory HDF5 file '{}'", name.string()));
  return File(id, name);
}

File File::openReadWrite(const std::filesystem::path& path) {
  return File(openExisting(path, H5F_ACC_RDWR, "reading and writing"), path);
}

File File::openReadOnly(const std::filesystem::path& path) {
  return File(openExisting(path, H5F_ACC_RDONLY, "reading"), path);
}

File::File(File&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), path_(std::move(other.path_)) {}

File::~File() { if (id_ >= 0) H5Fclose(id_); }

void File::fail(const std::string& what, const std::string& objpath) const {
  throw RunError(fmt::format("HDF5 file '{}': cannot {} '{}'", path_.string(), what, objpath));
}

bool File::exists(const std::string& objpath) const {
  // H5Lexists fails (rather than answering false) when a parent is missing, so walk the path.
  std::size_t end = 0;
  while (end != std::string::npos) {
    end = objpath.find('/', end + 1);
    const std::string prefix = objpath.substr(0, end);
    if (prefix.empty() || prefix == "/") continue;
    if (H5Lexists(id_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return true;
}

void File::createGroups(const std::string& objpath) {
  if (exists(objpath)) return;
  const Handle lcpl(intermediateGroupsLcpl(), H5Pclose);
  const hid_t group = H5Gcreate2(id_, objpath.c_str(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT);
  if (group < 0) fail("create group", objpath);
  H5Gclose(group);
}

void File::remove(const std::string& objpath) {
  if (H5Ldelete(id_, objpath.c_str(), H5P_DEFAULT) < 0) fail("delete", objpath);
}

std::vector<std::string> File::children(const std::string& group_path) const {
  std::vector<std::string> names;
  // `auto` accepts both H5L_info_t (HDF5 1.10) and H5L_info2_t (1.12+, where H5Literate_by_name
  // maps to H5Literate_by_name2).
  const auto collect = [](hid_t, const char* name, const auto*, void* out) -> herr_t {
    static_cast<std::vector<std::string>*>(out)->emplace_back(name);
    return 0;
  };
  if (H5Literate_by_name(id_, group_path.c_str(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect,
                         &names, H5P_DEFAULT) < 0) {
    fail("list group", group_path);
  }
  std::sort(names.begin(), names.end());  // the name index is sorted already; make it explicit
  return names;
}

template <class T>
void File::writeAs(const std::string& path, const std::vector<T>& data, Shape shape) {
  if (shape.empty()) shape = {data.size()};
  if (elementCount(shape) != data.size()) {
    fail(fmt::format("write {} values as shape ({}) to", data.size(), fmt::join(shape, ",")), path);
  }
  if (exists(path)) remove(path);
  const auto [file_type, mem_type] = fileAndMemoryTypes<T>();
  const int rank = static_cast<int>(shape.size());
  const Handle space(H5Screate_simple(rank, shape.data(), nullptr), H5Sclose);
  const Handle lcpl(intermediateGroupsLcpl(), H5Pclose);
  const Handle dataset(
      H5Dcreate2(id_, path.c_str(), file_type, space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!dataset.valid()) fail("create dataset", path);
  // An empty dataset has nothing to write (and HDF5 rejects a null buffer).
  if (!data.empty() &&
      H5Dwrite(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) {
    fail("write dataset", path);
  }
}

template <class T>
std::vector<T> File::readAs(const std::string& path, Shape* shape) const {
  const Handle dataset(H5Dopen2(id_, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) fail("open dataset", path);
  const Shape dims = dimensions(dataset.get());
  std::vector<T> data(elementCount(dims));
  // HDF5 converts from the stored type to T, so e.g. an int32 dataset reads as doubles.
  const hid_t mem_type = fileAndMemoryTypes<T>().second;
  if (!data.empty() &&
      H5Dread(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) {
    fail("read dataset", path);
  }
  if (shape != nullptr) *shape = dims;
  return data;
}

void File::write(const std::string& path, const std::vector<double>& data, Shape shape) {
  writeAs(path, data, std::move(shape));
}
void File::write(const std::string& path, const std::vector<std::int32_t>& data, Shape shape) {
  writeAs(path, data, std::move(shape));
}
void File::write(const std::string& path, const std::vector<std::int64_t>& data, Shape shape) {
  writeAs(path, data, std::move(shape));
}
void File::write(const std::string& path, const std::vector<std::int8_t>& data, Shape shape) {
  writeAs(path, data, std::move(shape));
}
void File::write(const std::string& path, const std::vector<std::uint8_t>& data, Shape shape) {
  writeAs(path, data, std::move(shape));
}

void File::write(const std::string& path, const std::vector<std::string>& data) {
  if (exists(path)) remove(path);
  const Handle type(utf8StringType(), H5Tclose);
  const hsize_t count = data.size();
  const Handle space(H5Screate_simple(1, &count, nullptr), H5Sclose);
  const Handle lcpl(intermediateGroupsLcpl(), H5Pclose);
  const Handle dataset(H5Dcreate2(id_, path.c_str(), type.get(), space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT),
                       H5Dclose);
  if (!dataset.valid()) fail("create dataset", path);
  // Variable-length strings are written as an array of char pointers.
  std::vector<const char*> pointers;
  for (const std::string& s : data) pointers.push_back(s.c_str());
  if (!data.empty() && H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0)
    fail("write dataset", path);
}

std::vector<std::string> File::readStrings(const std::string& path) const {
  const Handle dataset(H5Dopen2(id_, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) fail("open dataset", path);
  const Handle type(utf8StringType(), H5Tclose);
  std::vector<char*> pointers(elementCount(dimensions(dataset.get())), nullptr);
  if (!pointers.empty() &&
      H5Dread(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0)
    fail("read dataset", path);
  std::vector<std::string> strings;
  for (char* p : pointers) {
    strings.emplace_back(p != nullptr ? p : "");
    H5free_memory(p);  // HDF5 allocated each string
  }
  return strings;
}

std::vector<double> File::readDoubles(const std::string& path, Shape* shape) const {
  return readAs<double>(path, shape);
}
std::vector<std::int32_t> File::readInt32(const std::string& path, Shape* shape) const {
  return readAs<std::int32_t>(path, shape);
}
std::vector<std::int64_t> File::readInt64(const std::string& path, Shape* shape) const {
  return readAs<std::int64_t>(path, shape);
}
std::vector<std::int8_t> File::readInt8(const std::string& path, Shape* shape) const {
  return readAs<std::int8_t>(path, shape);
}
std::vector<std::uint8_t> File::readUInt8(const std::string& path, Shape* shape) const {
  return readAs<std::uint8_t>(path, shape);
}

Shape File::shape(const std::string& path) const {
  const Handle dataset(H5Dopen2(id_, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) fail("open dataset", path);
  return dimensions(dataset.get());
}

void File::setAttributeRaw(const std::string& objpath, const std::string& name, hid_t type,
                           const void* value, hssize_t count) {
  const std::string what = fmt::format("set attribute '{}' on", name);
  const Handle object(H5Oopen(id_, objpath.c_str(), H5P_DEFAULT), H5Oclose);
  if (!object.valid()) fail(what, objpath);
  if (H5Aexists(object.get(), name.c_str()) > 0) H5Adelete(object.get(), name.c_str());
  const hsize_t dims[1] = {static_cast<hsize_t>(count < 0 ? 0 : count)};
  const Handle space(count < 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims, nullptr), H5Sclose);
  const Handle attr(
      H5Acreate2(object.get(), name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  if (!attr.valid() || H5Awrite(attr.get(), type, value) < 0) fail(what, objpath);
}

void File::setAttribute(const std::string& objpath, const std::string& name, double value) {
  setAttributeRaw(objpath, name, H5T_NATIVE_DOUBLE, &value);
}
void File::setAttribute(const std::string& objpath, const std::string& name, std::int64_t value) {
  setAttributeRaw(objpath, name, H5T_NATIVE_INT64, &value);
}
void File::setAttribute(const std::string& objpath, const std::string& name,
                        const std::vector<std::int64_t>& values) {
  setAttributeRaw(objpath, name, H5T_NATIVE_INT64, values.data(), static_cast<hssize_t>(values.size()));
}
void File::setAttribute(const std::string& objpath, const std::string& name,
                        const std::string& value) {
  const Handle type(utf8StringType(), H5Tclose);
  const char* text = value.c_str();  // a variable-length string is written as a char pointer
  setAttributeRaw(objpath, name, type.get(), &text);
}

void File::readAttributeRaw(const std::string& objpath, const std::string& name, hid_t mem_type,
                            void* value) const {
  const std::string what = fmt::format("read attribute '{}' of", name);
  const Handle attr(
      H5Aopen_by_name(id_, objpath.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) fail(what, objpath);
  // Reading an array attribute into one scalar would overrun `value`.
  const Handle space(H5Aget_space(attr.get()), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1) fail(what, objpath);
  if (H5Aread(attr.get(), mem_type, value) < 0) fail(what, objpath);
}

bool File::attributeExists(const std::string& objpath, const std::string& name) const {
  return exists(objpath) && H5Aexists_by_name(id_, objpath.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

double File::attributeDouble(const std::string& objpath, const std::string& name) const {
  double value = 0.0;
  readAttributeRaw(objpath, name, H5T_NATIVE_DOUBLE, &value);
  return value;
}

std::int64_t File::attributeInt64(const std::string& objpath, const std::string& name) const {
  std::int64_t value = 0;
  readAttributeRaw(objpath, name, H5T_NATIVE_INT64, &value);
  return value;
}

std::string File::attributeString(const std::string& objpath, const std::string& name) const {
  const Handle type(utf8StringType(), H5Tclose);
  char* text = nullptr;  // HDF5 allocates the characters of a variable-length string
  readAttributeRaw(objpath, name, type.get(), &text);
  std::string value = text != nullptr ? text : "";
  H5free_memory(text);
  return value;
}

void File::linkExternal(const std::string& objpath, const std::string& file, const std::string& target) {
  const Handle lcpl(intermediateGroupsLcpl(), H5Pclose);
  if (H5Lcreate_external(file.c_str(), target.c_str(), id_, objpath.c_str(), lcpl.get(), H5P_DEFAULT) < 0)
    fail("create external link", objpath);
}

void File::flush() {
  if (H5Fflush(id_, H5F_SCOPE_GLOBAL) < 0) fail("flush", "/");
}

std::string File::image() {
  flush();
  const ssize_t size = H5Fget_file_image(id_, nullptr, 0);
  if (size < 0) fail("take the image of", "/");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (H5Fget_file_image(id_, bytes.data(), bytes.size()) != size) fail("take the image of", "/");
  return bytes;
}

}  // namespace cortex::h5
