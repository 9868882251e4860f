// The header's health badge follows the server: /api/v1/health is asked every few seconds, and the
// badge turns red (and says so) as soon as an answer fails or is late, green again once one comes.
import { api } from './api.js';
import { $ } from './dom.js';

const EVERY_MS = 2000;
const TIMEOUT_MS = 3000; // a stopped server accepts the connection and never answers

function show(up, text, detail) {
  const badge = $('#health');
  badge.textContent = text;
  badge.title = `${detail} (checked ${new Date().toLocaleTimeString()})`;
  badge.className = `health ${up ? 'ok' : 'bad'}`;
  badge.dataset.state = up ? 'up' : 'down';
}

async function check() {
  try {
    const h = await api('/health', { fetch: { signal: AbortSignal.timeout(TIMEOUT_MS), cache: 'no-store' } });
    show(true, `server ${h.version}`, 'the server answers');
  } catch (e) {
    show(false, 'server down', `the server does not answer: ${e}`);
  }
  setTimeout(check, EVERY_MS);
}

export function initHealth() {
  check();
}
