// The header's health badge follows the server: red (and saying so) while it does not answer, green
// once it does again. Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { startServer, openBrowser } from './support.mjs';

// The server is stopped (it accepts connections and answers none), resumed, killed, and started
// again on the same port.
test('the health badge turns red while the server does not answer and green when it answers again', async () => {
  let server = await startServer();
  const browser = await openBrowser(`${server.base}/`);
  const { page } = browser;
  try {
    const badge = (state) => page.locator(`#health[data-state=${state}]`);
    const expect = async (state, text) => {
      await badge(state).waitFor({ timeout: 15000 });
      assert.match(await page.locator('#health').innerText(), text);
    };
    const up = /^server \d+\.\d+\.\d+$/;
    await expect('up', up);
    assert.equal(await page.$eval('#health', (b) => getComputedStyle(b).color), 'rgb(139, 149, 163)');

    server.proc.kill('SIGSTOP');
    await expect('down', /^server down$/);
    assert.equal(await page.$eval('#health', (b) => getComputedStyle(b).color), 'rgb(255, 180, 180)');
    server.proc.kill('SIGCONT');
    await expect('up', up);

    await server.stop('SIGKILL');
    await expect('down', /^server down$/);
    server = await startServer({ port: server.port, stateDir: server.stateDir });
    await expect('up', up);
    assert.deepEqual(browser.errors, []);
  } finally {
    await browser.close();
    await server.remove();
  }
});
