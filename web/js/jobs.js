// What the panels following a background job (renders, prefiltered chains) share: the states in which
// it still runs, and how its progress is shown.
export const ACTIVE = new Set(['queued', 'running']);

// The job's progress on `bar` (the child of a .progress), its "id · status · 42%" on `status`, and
// `cancel` enabled while it runs and no cancel has been asked.
export function showProgress(job, { bar, status, cancel }) {
  const percent = Math.round((job.status === 'done' ? 1 : job.progress) * 1000) / 10;
  bar.style.width = `${percent}%`;
  bar.className = job.status;
  const cancelling = job.cancel_requested && ACTIVE.has(job.status) ? ' (cancelling)' : '';
  status.textContent = `${job.id} · ${job.status}${cancelling} · ${percent}%`;
  status.dataset.status = job.status;
  cancel.disabled = !ACTIVE.has(job.status) || job.cancel_requested;
}
