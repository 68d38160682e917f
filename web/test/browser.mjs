// The web playground in a real browser: Debian's Chromium, headless, driven
// through playwright-core against the page served on 127.0.0.1.
//
//   node web/test/browser.mjs        (after `bash web/build.sh`)
//
// Checks: the page loads with no console error; the determinism panel's
// browser hash equals the native CLI's and shows green; every scene runs
// 120 ticks; every built-in scene's hash after 300 ticks equals the hash the
// native CLI prints for the same scene and ticks (asked here, and the one
// built into the page); a click adds a body; a drag pushes a body; the
// grapple fires on a click, reels on a key, holds the player on the rope,
// and lets go on Space. Writes screenshots and results.json (with browser
// and native ms/step for large_pyramid and balls5000) to web/test/output/.
//
// Environment: CHROMIUM (default /usr/bin/chromium), CLOCKWORK2D_CLI (default
// <target dir>/release/clockwork2d, CARGO_TARGET_DIR honoured).
import { spawn, execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const HERE = dirname(fileURLToPath(import.meta.url));
const ROOT = resolve(HERE, '..', '..');
const WWW = join(ROOT, 'web', 'www');
const OUT = join(HERE, 'output');
const TARGET_DIR = resolve(ROOT, process.env.CARGO_TARGET_DIR || 'target');
const CLI = process.env.CLOCKWORK2D_CLI || join(TARGET_DIR, 'release', 'clockwork2d');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const SPEED_SCENES = ['large_pyramid', 'balls5000'];

let passed = 0;
let failed = 0;
function check(ok, what) {
  if (ok) {
    passed += 1;
    console.log(`ok   ${what}`);
  } else {
    failed += 1;
    console.log(`FAIL ${what}`);
  }
}

/** The native CLI's final line for `run SCENE --ticks N`. */
function nativeRun(scene, ticks) {
  const out = execFileSync(CLI, ['run', scene, '--ticks', String(ticks), '--hash-every', '0'], {
    encoding: 'utf8',
  });
  const m = out.match(/final tick (\d+) hash (0x[0-9a-f]{16}) bodies (\d+) ms_per_step ([0-9.]+)/);
  if (!m) throw new Error(`unexpected CLI output: ${out}`);
  return { tick: Number(m[1]), hash: m[2], bodies: Number(m[3]), msPerStep: Number(m[4]) };
}

/** python3 -m http.server on 127.0.0.1, a free port; resolves to its URL. */
function serve() {
  const server = spawn('python3', ['-u', '-m', 'http.server', '--bind', '127.0.0.1', '-d', WWW, '0'], {
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  return new Promise((ok, fail) => {
    const timer = setTimeout(() => fail(new Error('http.server did not start in 20 s')), 20000);
    server.stdout.on('data', (chunk) => {
      const m = String(chunk).match(/port (\d+)/);
      if (m) {
        clearTimeout(timer);
        ok({ server, url: `http://127.0.0.1:${m[1]}/` });
      }
    });
    server.on('exit', (code) => fail(new Error(`http.server exited with ${code}`)));
  });
}

async function main() {
  rmSync(OUT, { recursive: true, force: true });
  mkdirSync(OUT, { recursive: true });
  const { server, url } = await serve();
  const profile = mkdtempSync(join(tmpdir(), 'clockwork2d-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1400, height: 760 },
    args: [
      '--no-sandbox',
      '--disable-gpu',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
    ],
  });
  const results = { scenes: {}, speed: {}, determinism: null, wasm_bytes: null };
  try {
    const page = context.pages()[0] || (await context.newPage());
    const consoleErrors = [];
    page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
    page.on('pageerror', (e) => consoleErrors.push(String(e)));
    page.on('requestfailed', (r) => consoleErrors.push(`request failed: ${r.url()}`));
    const version = context.browser() ? context.browser().version() : '(persistent context)';
    console.log(`chromium ${version}; page ${url}`);

    await page.goto(`${url}?paused=1`);
    await page.evaluate(() => window.clockwork.ready);
    const native = await page.evaluate(() => window.clockwork.native());

    // Determinism panel: ran at load.
    const det = {
      browser: await page.textContent('#det-browser'),
      native: await page.textContent('#det-native'),
      green: await page.evaluate(() => document.querySelector('#det-verdict').classList.contains('equal')),
    };
    results.determinism = { ...native.determinism, browser: det.browser };
    check(det.native === native.determinism.hash && det.browser === det.native && det.green,
      `determinism panel: browser ${det.browser} = native ${det.native}, shown green`);
    await page.screenshot({ path: join(OUT, 'determinism.png') });

    // Every scene: 120 ticks; built-in scenes: the hash at 300 ticks.
    const scenes = await page.evaluate(() => window.clockwork.scenes());
    const builtin = scenes.filter((s) => s in native.scenes);
    check(builtin.length === Object.keys(native.scenes).length && builtin.length > 0,
      `the page offers every built-in scene (${builtin.length}) and the grapple arena`);
    for (const scene of scenes) {
      await page.evaluate((s) => { window.clockwork.pause(); window.clockwork.select(s); }, scene);
      const at120 = await page.evaluate(() => window.clockwork.step(120));
      check(at120.tick === 120 && at120.bodies > 0 && /^0x[0-9a-f]{16}$/.test(at120.hash),
        `${scene}: 120 ticks (${at120.bodies} bodies, ${at120.msPerStep.toFixed(3)} ms/step)`);
      await page.screenshot({ path: join(OUT, `scene-${scene}.png`) });
      if (!(scene in native.scenes)) continue;
      const at300 = await page.evaluate(() => window.clockwork.step(180));
      const cli = nativeRun(scene, 300);
      const shown = await page.evaluate(() => document.querySelector('#scene-check').classList.contains('equal'));
      results.scenes[scene] = { browser: at300.hash, native_cli: cli.hash, built_in: native.scenes[scene] };
      check(at300.tick === 300 && at300.hash === cli.hash && cli.hash === native.scenes[scene] && shown,
        `${scene}: tick 300 browser ${at300.hash} = native ${cli.hash}`);
    }

    // Speed: the same 300 ticks from a fresh build, browser against native.
    for (const scene of SPEED_SCENES) {
      const browser = await page.evaluate((s) => {
        window.clockwork.select(s);
        return window.clockwork.step(300).msPerStep;
      }, scene);
      const cli = nativeRun(scene, 300);
      results.speed[scene] = { ticks: 300, browser_ms_per_step: browser, native_ms_per_step: cli.msPerStep };
      console.log(`speed ${scene}: browser ${browser.toFixed(3)} ms/step, native ${cli.msPerStep.toFixed(3)} ms/step ` +
        `(x${(browser / cli.msPerStep).toFixed(2)})`);
    }

    // A click drops a body; a drag pushes one.
    await page.evaluate(() => { window.clockwork.select('stack'); window.clockwork.pause(); });
    const before = await page.evaluate(() => window.clockwork.state());
    const dropAt = await page.evaluate(() => window.clockwork.toPage(3, 8));
    await page.mouse.click(dropAt[0], dropAt[1]);
    const afterClick = await page.evaluate(() => window.clockwork.state());
    check(afterClick.bodies === before.bodies + 1, `a click adds a body (${before.bodies} -> ${afterClick.bodies})`);
    const top = await page.evaluate(() => {
      // The highest dynamic body of the stack (not the dropped one at x = 3).
      const b = window.clockwork.bodies();
      let best = null;
      for (let i = 0; i < b.length; i += 7) {
        if (b[i + 5] === 2 && Math.abs(b[i + 1] - 3) > 1 && (best === null || b[i + 2] > best[1])) best = [b[i + 1], b[i + 2]];
      }
      return best;
    });
    const from = await page.evaluate(([x, y]) => window.clockwork.toPage(x, y), top);
    const to = await page.evaluate(([x, y]) => window.clockwork.toPage(x + 2, y), top);
    await page.mouse.move(from[0], from[1]);
    await page.mouse.down();
    await page.mouse.move(to[0], to[1], { steps: 5 });
    await page.mouse.up();
    const pushed = await page.evaluate(([x, y]) => {
      window.clockwork.step(10);
      const b = window.clockwork.bodies();
      // The body that was at (x, y): the nearest dynamic body now at that height.
      let moved = null;
      for (let i = 0; i < b.length; i += 7) {
        if (b[i + 5] === 2 && Math.abs(b[i + 2] - y) < 0.5 && Math.abs(b[i + 1] - 3) > 1) moved = b[i + 1] - x;
      }
      return moved;
    }, top);
    // A drag of 2 units right asks for +6 units/s: over 10 ticks (1/6 s) the
    // box slides ~1 unit less friction (mu = 0.6 on its weight only slows it
    // by g·mu·t = 1 units/s): at least 0.5 units.
    check(pushed !== null && pushed > 0.5, `a drag pushes a body (moved ${pushed === null ? '?' : pushed.toFixed(2)} units right)`);
    await page.screenshot({ path: join(OUT, 'click-and-drag.png') });

    // The grapple: aim up and to the right, click, reel in, swing, let go.
    await page.evaluate(() => { window.clockwork.select('grapple'); window.clockwork.pause(); window.clockwork.step(30); });
    const start = await page.evaluate(() => window.clockwork.state());
    const [px, py] = start.grapple;
    const aimAt = await page.evaluate(([x, y]) => window.clockwork.toPage(x + 2, y + 6), [px, py]);
    await page.mouse.move(aimAt[0], aimAt[1]);
    await page.mouse.click(aimAt[0], aimAt[1]);
    const roped = await page.evaluate(() => window.clockwork.state());
    check(roped.constraints === 1 && roped.grapple.length === 5,
      `the grapple fires on a click (rope at (${roped.grapple.slice(2, 4).map((v) => v.toFixed(2)).join(', ')}), ` +
      `length ${roped.grapple[4]?.toFixed(3)})`);
    await page.keyboard.down('ArrowUp');
    const reeled = await page.evaluate(() => window.clockwork.step(10));
    await page.keyboard.up('ArrowUp');
    // Reeling takes 0.1 units per tick.
    check(reeled.grapple.length === 5 && Math.abs(roped.grapple[4] - reeled.grapple[4] - 1.0) < 1e-4,
      `reeling on a key shortens the rope by 0.1 per tick (${roped.grapple[4]?.toFixed(3)} -> ${reeled.grapple[4]?.toFixed(3)})`);
    await page.keyboard.down('d');
    const swung = await page.evaluate(() => window.clockwork.step(90));
    await page.keyboard.up('d');
    const [sx, sy, ax, ay, len] = swung.grapple;
    const dist = Math.hypot(sx - ax, sy - ay);
    // An ideal rope: the player never gets farther than its length (plus
    // the position solver's slop, a few thousandths of a unit).
    check(swung.grapple.length === 5 && dist <= len + 0.01,
      `the rope holds the swinging player (distance ${dist.toFixed(3)} <= length ${len.toFixed(3)})`);
    await page.screenshot({ path: join(OUT, 'grapple.png') });
    await page.keyboard.press('Space');
    const released = await page.evaluate(() => window.clockwork.state());
    check(released.constraints === 0 && released.grapple.length === 2, 'Space lets go of the rope');

    check(consoleErrors.length === 0, `no console error${consoleErrors.length ? ': ' + consoleErrors.join(' | ') : ''}`);
  } finally {
    await context.close();
    server.kill();
    rmSync(profile, { recursive: true, force: true });
  }
  writeFileSync(join(OUT, 'results.json'), JSON.stringify(results, null, 2) + '\n');
  console.log(`${passed} passed, ${failed} failed`);
  process.exitCode = failed === 0 ? 0 : 1;
}

main().catch((e) => {
  console.error(e);
  process.exitCode = 1;
});
