#include "server/maps/stored_maps.hpp"

#include <spdlog/spdlog.h>

#include "server/maps/envmap_loading.hpp"
#include "server/storage/data_dir.hpp"
#include "server/storage/resource_name.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

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
    spdlog::error("map '{}' is loaded but will not survive a restart: {}", entry->name, e.what());
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
  int restored = 0;
  for (const auto& [path, record] : app.state->read_records(app.state->maps_dir())) {
    try {
      restore_map(app, record);
      ++restored;
    } catch (const std::exception& e) {
      spdlog::warn("state: skipping map {}: {}", path.string(), e.what());
    }
  }
  spdlog::info("state: {} map(s) restored", restored);
}

}  // namespace lp::server
