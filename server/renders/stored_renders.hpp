#pragma once
// Render jobs across restarts: the records in the state directory become jobs again at start (a render
// that was queued or running becomes interrupted), and an interrupted render continues from its last
// finished pass.
#include <memory>

#include "server/app.hpp"
#include "server/renders/queue_render.hpp"
#include "server/renders/render_job.hpp"

namespace lp::server {

// Restores every readable record, oldest first, within the finished-job limits; a record that cannot
// be used is skipped with a warning, a finished render's record whose image is missing is dropped, and
// images no record names are removed (both logged). With --resume-interrupted, resumes the interrupted ones.
void restore_renders(App& app);

// Queues a continuation of an interrupted render, which replaces it under the same id; no job if the
// queue is full. Throws ApiError 409 if the job is not interrupted, its map is not loaded, or the map
// loaded under its name or a mesh object's model is not the one it was rendering (another content hash).
QueuedRender resume_render(App& app, const std::shared_ptr<RenderJob>& job);

}  // namespace lp::server
