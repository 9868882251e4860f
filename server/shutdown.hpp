#pragma once
// What the server does on SIGTERM or SIGINT, in order:
//  1. the transport refuses new requests; requests in flight are answered;
//  2. queued renders become interrupted at once; running renders get --shutdown-grace-s to finish the
//     pass they are in, and are halted after it; each keeps its state (renders/render_job.hpp);
//  3. every render event stream sees its render end, sends its final `end` event and closes;
//  4. the transport closes every connection.
// The caller then exits 0.
#include <chrono>

#include "server/app.hpp"
#include "server/server.hpp"

namespace lp::server {

// How long step 3 waits for the event streams to close, and how long the caller should wait for the
// transport to return after step 4 before it exits anyway (the state is written by then).
inline constexpr std::chrono::milliseconds kStreamDrain{1000};
inline constexpr std::chrono::milliseconds kConnectionDrain{2000};

void shut_down(App& app, Server& server);

}  // namespace lp::server
