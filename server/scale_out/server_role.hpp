#pragma once
// What a server does with --redis: accept jobs and split them into work items (api), take work items
// (worker), or both. Without --redis a server renders its own jobs, as one process.
#include "engine/core/enum_table.hpp"

namespace lp::server {

enum class ServerRole { Api, Worker, Both };

constexpr auto enum_entries(ServerRole) {
  return std::to_array<EnumEntry<ServerRole>>(
      {{ServerRole::Api, "api"}, {ServerRole::Worker, "worker"}, {ServerRole::Both, "both"}});
}

}  // namespace lp::server
