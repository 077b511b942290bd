#include "bindings/toml_from_dict.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "bindings/input_checks.hpp"
#include "bindings/interactive_run.hpp"

namespace granule::bindings {

namespace py = pybind11;

namespace {

// Deeper than any configuration goes (its tables are two levels deep, a shear history's points
// three): a limit far below the C++ stack's, so that no input can exhaust it.
constexpr int kMaxNesting = 64;
// Far beyond any configuration file (a shear history of a million points is ~40 MB of TOML);
// it keeps a mistaken path to a huge file from being read whole into memory.
constexpr off_t kMaxConfigFileBytes = off_t{256} << 20;

using TomlValue = std::variant<bool, std::int64_t, double, std::string, toml::table, toml::array>;

// Converts a dict's values to TOML, refusing what TOML cannot hold by its key path ("system.x",
// "boundary.shear_history[2]"): the config errors of the command line then name the same keys.
class TomlFromPython {
 public:
  toml::table table(const py::dict& dict, const std::string& prefix) {
    const Entered entered(*this, dict, prefix.empty() ? "config" : prefix.substr(0, prefix.size() - 1));
    toml::table table;
    // A list of the items (strong references): nothing below runs Python code that could change
    // the dict, but iterating a copy keeps that true whatever the values are.
    for (const py::handle item : py::list(dict.attr("items")())) {
      const py::tuple pair = py::reinterpret_borrow<py::tuple>(item);
      if (!py::isinstance<py::str>(pair[0])) {
        throw py::type_error(fmt::format("{}: keys must be strings, not {}", entered.where, type_name(pair[0])));
      }
      const std::string name = pair[0].cast<std::string>();
      std::visit([&](auto&& v) { table.insert(name, std::move(v)); }, value(pair[1], prefix + name));
    }
    return table;
  }

 private:
  // One dict or list being converted: refuses a container that holds itself and nesting deeper
  // than kMaxNesting, each of which would recurse without end.
  struct Entered {
    Entered(TomlFromPython& converter, py::handle container, std::string path)
        : open(converter.open_), where(std::move(path)) {
      if (std::find(open.begin(), open.end(), container.ptr()) != open.end()) {
        throw py::value_error(fmt::format("{}: the {} contains itself (a cycle): a configuration is a tree",
                                          where, type_name(container)));
      }
      if (open.size() >= kMaxNesting) {
        throw py::value_error(fmt::format("{}: nested deeper than {} levels", where, kMaxNesting));
      }
      open.push_back(container.ptr());
    }
    ~Entered() { open.pop_back(); }
    Entered(const Entered&) = delete;
    Entered& operator=(const Entered&) = delete;

    std::vector<PyObject*>& open;
    std::string where;
  };

  // The TOML value of `value` (the key path `where` names it in errors).
  TomlValue value(py::handle value, const std::string& where) {
    // NumPy scalars (np.int64(5), np.float32(0.5), np.bool_) are the numbers they hold.
    const py::module_ numpy = py::module_::import("numpy");
    if (py::isinstance(value, numpy.attr("bool_"))) return value.cast<bool>();
    if (py::isinstance(value, numpy.attr("integer"))) return integer(py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr())), where);
    if (py::isinstance(value, numpy.attr("floating"))) return value.cast<double>();
    // bool before int: Python's True is an int too.
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (py::isinstance<py::int_>(value)) return integer(value, where);
    if (py::isinstance<py::float_>(value)) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::dict>(value)) return table(value.cast<py::dict>(), where + ".");
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      const Entered entered(*this, value, where);
      toml::array array;
      std::size_t index = 0;
      for (const py::handle item : py::list(py::reinterpret_borrow<py::object>(value))) {
        std::visit([&](auto&& v) { array.push_back(std::move(v)); }, this->value(item, fmt::format("{}[{}]", where, index++)));
      }
      return array;
    }
    throw py::type_error(fmt::format("{}: a value of type {} is not a TOML value (bool, int, float, str, list, tuple or dict; "
                                     "NumPy scalars too)", where, type_name(value)));
  }

  // TOML integers are 64-bit: a larger Python int is refused rather than rounded.
  static std::int64_t integer(py::handle value, const std::string& where) {
    if (!value) throw py::error_already_set();
    int overflow = 0;
    const long long result = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
    if (overflow != 0) {
      throw std::overflow_error(fmt::format("{}: an integer of {} bits does not fit in TOML's 64-bit integers "
                                            "[-2^63, 2^63 - 1]", where, value.attr("bit_length")().cast<long long>()));
    }
    if (result == -1 && PyErr_Occurred()) throw py::error_already_set();
    return result;
  }

  std::vector<PyObject*> open_;
};

[[noreturn]] void raise_os_error(int error, const std::string& path) {
  errno = error;
  // OSError(errno, …) is the subclass the errno names: FileNotFoundError, IsADirectoryError,
  // PermissionError.
  PyErr_SetFromErrnoWithFilenameObject(PyExc_OSError, py::str(path).ptr());
  throw py::error_already_set();
}

// A configuration file must be a readable regular file of a configuration's size: anything else
// raises the OSError Python's open() would, or ConfigError, before the file is read.
void check_config_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);  // O_NONBLOCK: a FIFO does not wait
  if (fd < 0) raise_os_error(errno, path);
  struct stat status {};
  const int stat_result = fstat(fd, &status);
  const int stat_error = errno;
  ::close(fd);
  if (stat_result != 0) raise_os_error(stat_error, path);
  if (S_ISDIR(status.st_mode)) raise_os_error(EISDIR, path);
  if (!S_ISREG(status.st_mode)) throw ConfigError(path + ": not a regular file (a configuration is a TOML file)");
  if (status.st_size > kMaxConfigFileBytes) {
    throw ConfigError(fmt::format("{}: {} bytes, more than a configuration file holds ({} MiB at the most)", path,
                                  status.st_size, kMaxConfigFileBytes >> 20));
  }
}

}  // namespace

std::string toml_text_from_dict(const py::dict& config) {
  std::ostringstream text;
  text << TomlFromPython().table(config, "");
  return text.str();
}

RunConfig run_config_from_python(const py::object& config, const std::vector<std::string>& overrides) {
  if (py::isinstance<py::dict>(config))
    return parse_run_config(toml_text_from_dict(config.cast<py::dict>()), overrides);
  const std::string path = path_argument(config, "config", "a dict or the path of a TOML file");
  check_config_file(path);
  return load_run_config(path, overrides);
}

}  // namespace granule::bindings
