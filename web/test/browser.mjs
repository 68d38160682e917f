// The web playground in a real browser: Debian's Chromium, headless, driven
// through playwright-core against the page served on 127.0.0.1.
//
//   node web/test/browser.mjs        (after `bash web/build.sh`)
//
// Checks: the page loads with no console error; the determinism panel's
// browser hash equals the native CLI's and shows green; every scene runs
// 120 ticks; every built-in scene's hash after 300 ticks equals the hash the
// native CLI prints for the same scene and ticks (asked here, and the one
// built into the page); the scene menu, the step and play/pause buttons and
// the N key work and the readout shows tick, hash and ms/step; a click adds
// a ball (or a box, when chosen) where it was; a drag pushes a body; the
// grapple fires on a click, reels on a key, holds the player on the rope,
// and lets go on Space; on the ground D/A push the player and W jumps. Writes screenshots and results.json to
// web/test/output/, and prints the hash agreement table (browser against
// native), browser and native ms/step for large_pyramid and balls5000, and
// the .wasm size.
//
// Environment: CHROMIUM (default /usr/bin/chromium), CLOCKWORK2D_CLI (default
// <target dir>/release/clockwork2d, CARGO_TARGET_DIR honoured), SPEED_ROUNDS
// (browser/native speed pairs per scene, default 1).
import { spawn, execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
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
const SPEED_ROUNDS = Math.max(1, Number(process.env.SPEED_ROUNDS || 1));

function median(values) {
  const v = [...values].sort((a, b) => a - b);
  return v.length % 2 ? v[(v.length - 1) / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
}

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

    // Speed: the same 300 ticks from a fresh build, browser against native,
    // alternating (SPEED_ROUNDS rounds, default 1; medians reported).
    for (const scene of SPEED_SCENES) {
      const browser = [];
      const nativeMs = [];
      for (let round = 0; round < SPEED_ROUNDS; round += 1) {
        browser.push(await page.evaluate((s) => {
          window.clockwork.select(s);
          return window.clockwork.step(300).msPerStep;
        }, scene));
        nativeMs.push(nativeRun(scene, 300).msPerStep);
      }
      const b = median(browser), n = median(nativeMs);
      results.speed[scene] = { ticks: 300, rounds: SPEED_ROUNDS, browser_ms_per_step: browser, native_ms_per_step: nativeMs };
      console.log(`speed ${scene} (300 ticks, median of ${SPEED_ROUNDS}): browser ${b.toFixed(3)} ms/step, ` +
        `native ${n.toFixed(3)} ms/step (browser/native ${(b / n).toFixed(2)})`);
    }

    // The controls a person uses: the scene menu, the step and play/pause
    // buttons, N for one step; the readout shows the world's tick and hash
    // and a ms/step once steps were timed.
    await page.selectOption('#scene', 'balls');
    const chosen = await page.evaluate(() => window.clockwork.state());
    check(chosen.scene === 'balls' && chosen.tick === 0, `the scene menu loads a scene (${chosen.scene} at tick ${chosen.tick})`);
    await page.click('#step');
    await page.click('#step');
    const stepped = await page.evaluate(() => window.clockwork.state());
    const playLabel = await page.textContent('#play');
    check(stepped.tick === 2 && playLabel === 'play', `the step button steps once, paused (tick ${stepped.tick}, button "${playLabel}")`);
    await page.keyboard.press('n');
    const keyed = await page.evaluate(() => window.clockwork.state());
    check(keyed.tick === 3, `N steps once (tick ${keyed.tick})`);
    await page.click('#play');
    await page.waitForFunction(() => window.clockwork.state().tick >= 30, null, { timeout: 30000 });
    check(await page.textContent('#play') === 'pause', 'the play button runs the scene by itself (tick 30 reached)');
    await page.click('#play');
    const pausedAt = await page.evaluate(() => window.clockwork.state().tick);
    await page.waitForTimeout(300);
    const stillAt = await page.evaluate(() => window.clockwork.state().tick);
    check(stillAt === pausedAt, `the pause button stops it (tick ${pausedAt}, still ${stillAt} after 0.3 s)`);
    await page.waitForTimeout(50); // one animation frame: the readout is refreshed every frame
    const readout = {
      tick: await page.textContent('#tick'),
      hash: await page.textContent('#hash'),
      ms: await page.textContent('#ms'),
    };
    const now = await page.evaluate(() => window.clockwork.state());
    check(readout.tick === String(now.tick) && readout.hash === now.hash && Number(readout.ms) > 0,
      `the readout shows tick ${readout.tick}, hash ${readout.hash}, ${readout.ms} ms/step`);
    await page.screenshot({ path: join(OUT, 'controls.png') });

    // A click drops a body; a drag pushes one.
    await page.evaluate(() => { window.clockwork.select('stack'); window.clockwork.pause(); });
    const before = await page.evaluate(() => window.clockwork.state());
    const dropAt = await page.evaluate(() => window.clockwork.toPage(3, 8));
    await page.mouse.click(dropAt[0], dropAt[1]);
    const afterClick = await page.evaluate(() => window.clockwork.state());
    // The new body is the last one, a dynamic ball where the click was, to
    // within the mouse's rounding to whole page pixels (1.5 pixels here).
    const newest = (b) => b.slice(b.length - 7);
    const pixel = await page.evaluate(() => 1 / (window.clockwork.toPage(1, 0)[0] - window.clockwork.toPage(0, 0)[0]));
    const ball = newest(await page.evaluate(() => window.clockwork.bodies()));
    check(afterClick.bodies === before.bodies + 1 && ball[0] === 0 && ball[5] === 2 &&
      Math.hypot(ball[1] - 3, ball[2] - 8) < 1.5 * pixel,
      `a click adds a ball there (${before.bodies} -> ${afterClick.bodies} bodies, at (${ball[1].toFixed(3)}, ${ball[2].toFixed(3)}))`);
    await page.check('input[name="shape"][value="box"]');
    const boxAt = await page.evaluate(() => window.clockwork.toPage(3, 11));
    await page.mouse.click(boxAt[0], boxAt[1]);
    const box = newest(await page.evaluate(() => window.clockwork.bodies()));
    const afterBox = await page.evaluate(() => window.clockwork.state());
    check(afterBox.bodies === before.bodies + 2 && box[0] === 1 && box[5] === 2 &&
      Math.hypot(box[1] - 3, box[2] - 11) < 1.5 * pixel,
      `with "box" chosen a click adds a box there (at (${box[1].toFixed(3)}, ${box[2].toFixed(3)}))`);
    const top = await page.evaluate(() => {
      // The highest dynamic body of the stack (not the dropped ones at x = 3).
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

    // On the ground, D and A push the player sideways and W jumps.
    await page.evaluate(() => { window.clockwork.select('grapple'); window.clockwork.pause(); window.clockwork.step(30); });
    const standing = (await page.evaluate(() => window.clockwork.state())).grapple;
    await page.keyboard.down('d');
    const walkedRight = (await page.evaluate(() => window.clockwork.step(20))).grapple;
    await page.keyboard.up('d');
    await page.keyboard.down('a');
    const walkedLeft = (await page.evaluate(() => window.clockwork.step(40))).grapple;
    await page.keyboard.up('a');
    // A held key adds 0.2 units/s per tick (12 units/s²) against the ground's
    // Coulomb friction mu·g = 0.6·9.8 = 5.9 units/s²: from rest, 20 ticks
    // (1/3 s) travel ½·6.1·(1/3)² = 0.34 units. Ask for half of that.
    check(walkedRight[0] - standing[0] > 0.17 && walkedRight[0] - walkedLeft[0] > 0.17,
      `D and A push the player (x ${standing[0].toFixed(2)} -> ${walkedRight[0].toFixed(2)} -> ${walkedLeft[0].toFixed(2)})`);
    await page.evaluate(() => window.clockwork.step(60));
    const landed = (await page.evaluate(() => window.clockwork.state())).grapple;
    await page.keyboard.down('w');
    await page.evaluate(() => window.clockwork.step(1));
    await page.keyboard.up('w');
    const jumped = (await page.evaluate(() => window.clockwork.step(9))).grapple;
    // Take-off at 7 units/s: after 10 ticks (1/6 s) y rose 7/6 - g/72 ~ 1.03.
    check(jumped[1] - landed[1] > 0.5, `W jumps off the ground (y ${landed[1].toFixed(2)} -> ${jumped[1].toFixed(2)})`);

    check(consoleErrors.length === 0, `no console error${consoleErrors.length ? ': ' + consoleErrors.join(' | ') : ''}`);
  } finally {
    await context.close();
    server.kill();
    rmSync(profile, { recursive: true, force: true });
  }
  const wasmPath = join(WWW, 'pkg', 'clockwork2d_web_bg.wasm');
  const wasm = readFileSync(wasmPath);
  results.wasm_bytes = wasm.length;
  results.wasm_gzip9_bytes = gzipSync(wasm, { level: 9 }).length;
  writeFileSync(join(OUT, 'results.json'), JSON.stringify(results, null, 2) + '\n');
  // The figures, as a table: browser against native.
  console.log(`\n| scene | browser hash at tick 300 | native CLI hash | equal |\n|---|---|---|---|`);
  for (const [scene, r] of Object.entries(results.scenes)) {
    console.log(`| ${scene} | ${r.browser} | ${r.native_cli} | ${r.browser === r.native_cli ? 'yes' : 'NO'} |`);
  }
  if (results.determinism) {
    const d = results.determinism;
    console.log(`| determinism panel: ${d.scene}, seed ${d.seed}, ${d.ticks} ticks | ${d.browser} | ${d.hash} | ${d.browser === d.hash ? 'yes' : 'NO'} |`);
  }
  console.log(`\n| scene (300 ticks) | browser ms/step | native ms/step | browser/native |\n|---|---:|---:|---:|`);
  for (const [scene, r] of Object.entries(results.speed)) {
    const b = median(r.browser_ms_per_step), n = median(r.native_ms_per_step);
    console.log(`| ${scene} | ${b.toFixed(2)} | ${n.toFixed(2)} | ${(b / n).toFixed(2)} |`);
  }
  console.log(`\nwasm: ${results.wasm_bytes} bytes, ${results.wasm_gzip9_bytes} gzipped (node zlib, level 9)\n`);
  console.log(`${passed} passed, ${failed} failed`);
  process.exitCode = failed === 0 ? 0 : 1;
}

main().catch((e) => {
  console.error(e);
  process.exitCode = 1;
});
