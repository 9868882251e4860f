#include "server/maps/stored_maps.hpp"

#include <spdlog/spdlog.h>

#include <set>

#include "server/maps/envmap_loading.hpp"
#include "server/storage/data_dir.hpp"
#include "server/storage/resource_name.hpp"
#include "server/storage/storage_error.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

struct MissingFile {};  // a record whose uploaded file is gone

constexpr int kRecordVersion = 1;
constexpr std::string_view kPathSource = "path:";

fs::path record_path(const StateStore& store, const std::string& name) {
  return store.maps_dir() / (name + ".json");
}

// The uploaded file of a map, named by the map and its format (both checked when read back).
std::string upload_file_name(const std::string& name, const std::string& format) {
  return name + "." + format;
}

// The layout the file was loaded in (records written before projections have none: lat-long).
Projection record_projection(const nlohmann::json& record) {
  const auto projection = parse_enum<Projection>(record.value("projection", enum_name(Projection::LatLong)));
  if (!projection) throw std::invalid_argument("unknown projection");
  return *projection;
}

// A file no record names (an upload a crash cut short before its record, or a delete left): neither a
// record, nor named by one, nor the file of a record that could not be read (kept for the operator).
bool is_leftover(const fs::path& file, const std::set<std::string>& named) {
  if (file.extension() == ".json" || named.contains(file.filename().string())) return false;
  std::error_code ec;
  return !fs::exists(file.parent_path() / (file.stem().string() + ".json"), ec);
}

void restore_map(App& app, const nlohmann::json& record) {
  if (record.at("version").get<int>() != kRecordVersion)
    throw std::invalid_argument("unknown record version");
  const auto name = record.at("name").get<std::string>();
  const auto source = record.at("source").get<std::string>();
  const auto file = record.at("file").get<std::string>();
  if (!valid_resource_name(name)) throw std::invalid_argument("not a map name: '" + name + "'");
  if (source.rfind(kPathSource, 0) == 0) {
    const auto path = resolve_in_data_dir(app.options, source.substr(kPathSource.size()), "path");
    register_envmap_file(app, name, path, source, kDefaultInvalidPixelPolicy, record_projection(record));
  } else {
    if (file != upload_file_name(name, record.at("format").get<std::string>()))
      throw std::invalid_argument("the file name is not the map's");
    if (!fs::exists(app.state->maps_dir() / file)) throw MissingFile();
    register_envmap_file(app, name, app.state->maps_dir() / file, source, kDefaultInvalidPixelPolicy,
                         record_projection(record));
  }
}

}  // namespace

void keep_map(App& app, const std::shared_ptr<const EnvMapEntry>& entry, std::span<const uint8_t> uploaded) {
  if (!app.state) return;
  StateStore& store = *app.state;
  std::lock_guard lock(store.maps_mutex());
  if (app.envmaps.find(entry->id) != entry) return;  // deleted before it could be kept
  const std::string file = uploaded.empty() ? "" : upload_file_name(entry->name, entry->format);
  try {
    if (!file.empty()) store.write_bytes(store.maps_dir() / file, uploaded);
    store.write_record(record_path(store, entry->name),
                       {{"version", kRecordVersion},
                        {"name", entry->name},
                        {"format", entry->format},
                        {"source", entry->source},
                        {"file", file},
                        {"projection", enum_name(entry->source_projection)}});
  } catch (const std::exception& e) {
    app.envmaps.remove(entry->id);
    if (!file.empty()) store.remove(store.maps_dir() / file);
    throw storage_refusal(e, "the map '" + entry->name + "'");
  }
}

bool remove_map(App& app, const std::string& id) {
  if (!app.state) return app.envmaps.remove(id);
  StateStore& store = *app.state;
  std::lock_guard lock(store.maps_mutex());
  const auto entry = app.envmaps.find(id);
  if (!entry || !app.envmaps.remove(id)) return false;
  store.remove(record_path(store, entry->name));  // the record first: without it the file is never read
  if (entry->source.rfind(kPathSource, 0) != 0)
    store.remove(store.maps_dir() / upload_file_name(entry->name, entry->format));
  return true;
}

void restore_maps(App& app) {
  const StateStore& store = *app.state;
  int restored = 0;
  std::set<std::string> named;  // files of the records kept
  for (const auto& [path, record] : store.read_records(store.maps_dir())) {
    try {
      named.insert(record.value("file", ""));
      restore_map(app, record);
      ++restored;
    } catch (const MissingFile&) {
      spdlog::warn("state: dropping {}: the map's file is missing", fs::relative(path, store.dir()).string());
      store.remove(path);
    } catch (const std::exception& e) {
      spdlog::warn("state: skipping map {}: {}", path.string(), e.what());
    }
  }
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(store.maps_dir(), ec))
    if (is_leftover(entry.path(), named)) store.remove_leftover(entry.path());
  spdlog::info("state: {} map(s) restored", restored);
}

}  // namespace lp::server
