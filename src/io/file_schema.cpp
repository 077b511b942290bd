#include "io/file_schema.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <cctype>
#include <cmath>
#include <algorithm>
#include <map>
#include <string_view>

#include "io/hdf5_util.hpp"
#include "io/io_error.hpp"

namespace granule::h5 {

namespace {

// A group may not list more members than this: no Granule file comes near, and a damaged link
// table must not make the check itself the allocation it guards against.
constexpr std::size_t kMostMembers = 100000;

struct Check {
  std::string path;
  hid_t file;
  // Bound dimension names: the value and the dataset that bound it.
  std::map<std::string, std::pair<hsize_t, std::string>> bound;

  [[noreturn]] void refuse(const std::string& what) const { throw InputError(path + ": " + what); }
};

std::vector<std::string> members(const Check& check, const std::string& group) {
  std::vector<std::string> names;
  const auto visit = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
    auto& list = *static_cast<std::vector<std::string>*>(data);
    if (list.size() >= kMostMembers) return 1;
    list.push_back(name);
    return 0;
  };
  hsize_t index = 0;
  if (H5Literate_by_name(check.file, group.c_str(), H5_INDEX_NAME, H5_ITER_INC, &index, visit, &names, H5P_DEFAULT) < 0) {
    check.refuse("cannot list the members of group " + group);
  }
  if (names.size() >= kMostMembers) check.refuse("group " + group + " has more members than a Granule file holds");
  return names;
}

// Whether every link on the way to `path` exists (H5Lexists fails on a missing parent).
bool exists(hid_t file, const std::string& path) {
  for (std::size_t end = path.find('/'); ; end = path.find('/', end + 1)) {
    if (H5Lexists(file, path.substr(0, end).c_str(), H5P_DEFAULT) <= 0) return false;
    if (end == std::string::npos) return true;
  }
}

H5O_type_t object_type(const Check& check, const std::string& path) {
  H5O_info_t info{};
  if (H5Oget_info_by_name2(check.file, path.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) {
    check.refuse("cannot read object " + path);
  }
  return info.type;
}

// The concrete paths a rule's path stands for, with the member its "*" matched ("" without one):
// the members of the group whose names begin and end as the starred name does.
std::vector<std::pair<std::string, std::string>> expand(const Check& check, const std::string& pattern) {
  const std::size_t star = pattern.find('*');
  if (star == std::string::npos) return {{pattern, ""}};
  const std::size_t begin = pattern.rfind('/', star) == std::string::npos ? 0 : pattern.rfind('/', star) + 1;
  const std::size_t end = std::min(pattern.find('/', star), pattern.size());
  const std::string group = begin == 0 ? "." : pattern.substr(0, begin - 1);
  const std::string prefix = pattern.substr(begin, star - begin), suffix = pattern.substr(star + 1, end - star - 1);
  if (group != "." && !exists(check.file, group)) return {};
  std::vector<std::pair<std::string, std::string>> paths;
  for (const std::string& member : members(check, group)) {
    if (member.size() < prefix.size() + suffix.size() || !member.starts_with(prefix) || !member.ends_with(suffix)) continue;
    paths.emplace_back(pattern.substr(0, begin) + member + pattern.substr(end), member);
  }
  return paths;
}

// The group a path is in ("." for the file's own members).
std::string parent(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

bool group_exists(hid_t file, const std::string& group) { return group == "." || exists(file, group); }

struct Dimension {
  std::string name;  // empty for a fixed size
  hsize_t offset;    // the fixed size, or what is added to the name's value
};

std::vector<Dimension> parse_shape(std::string_view shape) {
  std::vector<Dimension> dims;
  while (!shape.empty()) {
    const std::size_t comma = shape.find(',');
    const std::string_view token = shape.substr(0, comma);
    const std::size_t plus = token.find('+');
    if (std::isdigit(static_cast<unsigned char>(token[0]))) {
      dims.push_back({"", std::stoull(std::string(token))});
    } else {
      dims.push_back({std::string(token.substr(0, plus)),
                      plus == std::string_view::npos ? 0 : std::stoull(std::string(token.substr(plus + 1)))});
    }
    shape = comma == std::string_view::npos ? std::string_view{} : shape.substr(comma + 1);
  }
  return dims;
}

// Names in lower case are bound per member of the group a "*" ran over.
std::string binding_key(const Dimension& d, const std::string& member) {
  return std::islower(static_cast<unsigned char>(d.name[0])) && !member.empty() ? member + "/" + d.name : d.name;
}

void check_shape(Check& check, const std::string& path, const std::string& member, const char* shape) {
  const std::vector<Dimension> expected = parse_shape(shape);
  const std::vector<hsize_t> have = dataset_shape(check.file, path.c_str());
  bool fits = have.size() == expected.size();
  std::string wanted, because;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const Dimension& d = expected[k];
    std::string text = d.name.empty() ? fmt::format("{}", d.offset) : d.offset ? fmt::format("{}+{}", d.name, d.offset) : d.name;
    if (!d.name.empty()) {
      const auto found = check.bound.find(binding_key(d, member));
      if (found != check.bound.end()) {
        text += fmt::format(" = {}", found->second.first + d.offset);
        because += fmt::format("{}{} as {} has it", because.empty() ? "; " : ", ", d.name, found->second.second);
        fits = fits && have[k] == found->second.first + d.offset;
      } else if (fits && have[k] >= d.offset) {
        check.bound[binding_key(d, member)] = {have[k] - d.offset, path};
      } else {
        fits = false;
      }
    } else {
      fits = fits && have[k] == d.offset;
    }
    wanted += (k ? ", " : "") + text;
  }
  if (!fits) {
    check.refuse("dataset " + path + " has shape " + shape_text(have) + "; expected " +
                 (expected.empty() ? std::string("a scalar") : "(" + wanted + (expected.size() == 1 ? ",)" : ")")) + because);
  }
}

void check_numbers(const Check& check, const std::vector<double>& values, Values kind, const std::string& what) {
  if (kind != Values::kFinite) return;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values[k])) {
      check.refuse(what + " holds " + std::to_string(values[k]) + " at index " + std::to_string(k) + "; expected finite numbers");
    }
  }
}

void check_dataset(Check& check, const DatasetRule& rule) {
  for (const auto& [path, member] : expand(check, rule.path)) {
    if (!exists(check.file, path)) {
      if (rule.required && group_exists(check.file, parent(path))) check.refuse("has no dataset " + path);
      continue;
    }
    if (object_type(check, path) != H5O_TYPE_DATASET) check.refuse(path + " is not a dataset");
    check_shape(check, path, member, rule.shape);
    if (rule.values == Values::kIntegers) {
      if (!stored_as_integers(check.file, path.c_str())) check.refuse("dataset " + path + " is not stored as integers");
      continue;
    }
    check_numbers(check, read_values(check.file, path.c_str()), rule.values, "dataset " + path);
  }
}

void check_attribute(const Check& check, const AttributeRule& rule) {
  for (const auto& [path, member] : expand(check, rule.object)) {
    if (!group_exists(check.file, path)) continue;  // a missing group is the groups' or datasets' refusal
    const Handle object(H5Oopen(check.file, path.c_str(), H5P_DEFAULT), H5Oclose);
    if (object.get() < 0) check.refuse("cannot open object " + path);
    const char* name = rule.name.c_str();
    const std::string attribute = "attribute " + rule.name + (path == "." ? "" : " of " + path);
    if (!has_attribute(object.get(), name)) {
      if (rule.required) check.refuse("has no " + attribute);
      continue;
    }
    try {
      if (rule.values == Values::kText) {
        read_string_attribute(object.get(), name);
      } else if (rule.values == Values::kIntegers) {
        std::vector<long long> integers(static_cast<std::size_t>(rule.count));
        read_attribute_values(object.get(), name, H5T_NATIVE_LLONG, integers.data(), integers.size());
      } else {
        std::vector<double> values(static_cast<std::size_t>(rule.count));
        read_attribute_values(object.get(), name, H5T_NATIVE_DOUBLE, values.data(), values.size());
        check_numbers(check, values, rule.values, attribute);
      }
    } catch (const InputError& error) {
      if (path == ".") throw;
      throw InputError(std::string(error.what()) + " (" + path + ")");
    }
  }
}

void check_group(const Check& check, const std::string& pattern) {
  for (const auto& [path, member] : expand(check, pattern)) {
    if (!group_exists(check.file, path)) {
      if (group_exists(check.file, parent(path))) check.refuse("has no group " + path);
      continue;
    }
    if (object_type(check, path) != H5O_TYPE_GROUP) check.refuse(path + " is not a group");
  }
}

std::vector<std::string> all_datasets(const Check& check) {
  std::vector<std::string> datasets;
  const auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    auto& list = *static_cast<std::vector<std::string>*>(data);
    if (list.size() >= kMostMembers) return 1;
    if (info->type == H5O_TYPE_DATASET) list.push_back(name);
    return 0;
  };
  if (H5Ovisit2(check.file, H5_INDEX_NAME, H5_ITER_INC, visit, &datasets, H5O_INFO_BASIC) < 0) {
    check.refuse("cannot list its datasets");
  }
  return datasets;
}

}  // namespace

void check_file_schema(const std::string& path, const FileSchema& schema) {
  Handle file = open_file(path);
  Check check{path, file.get(), {}};
  const std::string format = has_attribute(file.get(), "format") ? read_string_attribute(file.get(), "format") : "";
  if (format != schema.format) check.refuse(std::string("is not a Granule ") + schema.format + " file (format \"" + format + "\")");
  const int version = read_attribute<int>(file.get(), "format_version", H5T_NATIVE_INT);
  if (version < schema.oldest_version || version > schema.newest_version) {
    check.refuse("format_version " + std::to_string(version) + " is not one this Granule reads (" +
                 std::to_string(schema.oldest_version) + " … " + std::to_string(schema.newest_version) + ")");
  }
  for (const std::string& dataset : all_datasets(check)) require_whole(file.get(), dataset.c_str());
  for (const std::string& group : schema.groups) check_group(check, group);
  for (const DatasetRule& rule : schema.datasets) check_dataset(check, rule);
  for (const AttributeRule& rule : schema.attributes) check_attribute(check, rule);
  file.close();
}

}  // namespace granule::h5
