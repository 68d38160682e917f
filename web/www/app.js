// The clockwork2d playground: the page owns the canvas, the mouse and the
// keyboard; the wasm module (web/src/) owns the world. Every number drawn
// here comes from the world's fixed-point state, converted once to f32.
import init, { Playground, sceneNames, determinismHash } from './pkg/clockwork2d_web.js';

// Layout of the draw lists (web/src/draw.rs).
const BODY_STRIDE = 7;
const CONSTRAINT_STRIDE = 6;
// A drag of one world unit asks for a velocity change of DRAG_GAIN units/s.
const DRAG_GAIN = 3;
// Mouse travel (pixels) below which a press is a click, not a drag.
const CLICK_SLOP = 4;
// ms/step is averaged over this many recent steps.
const TIMING_WINDOW = 60;

const $ = (id) => document.getElementById(id);
const canvas = $('view');
const ctx = canvas.getContext('2d');

let native = null; // web/www/native.json, written by web/build.sh
let pg = null; // the Playground
let playing = true;
let camera = { cx: 0, cy: 0, scale: 20 };
let stepTimes = [];
let sceneCheck = null; // 'equal' | 'different' once the scene reaches native.scene_ticks
let drag = null; // { start: world point, startPx, nowPx, now }
let mouseWorld = null;
const keys = new Set();

function showError(message) {
  $('error').textContent = message;
}

function guard(action) {
  try {
    return action();
  } catch (e) {
    // The module throws its refusal as a string (an invalid input, not a bug).
    showError(String(e));
    return undefined;
  }
}

// --- camera -----------------------------------------------------------------

function frameScene() {
  const b = pg.bodies();
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < b.length; i += BODY_STRIDE) {
    if (b[i + 6] === 2) continue; // frozen bodies are outside the bounds
    x0 = Math.min(x0, b[i + 1] - b[i + 3]);
    x1 = Math.max(x1, b[i + 1] + b[i + 3]);
    y0 = Math.min(y0, b[i + 2] - b[i + 4]);
    y1 = Math.max(y1, b[i + 2] + b[i + 4]);
  }
  if (!Number.isFinite(x0)) { x0 = -10; x1 = 10; y0 = -1; y1 = 10; }
  // Room around the scene, more above it (things get dropped from there).
  const w = Math.max(x1 - x0, 1), h = Math.max(y1 - y0, 1);
  x0 -= 0.08 * w; x1 += 0.08 * w; y0 -= 0.08 * h; y1 += 0.3 * h;
  const scale = Math.min(canvas.width / (x1 - x0), canvas.height / (y1 - y0));
  camera = { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, scale };
}

function toScreen(x, y) {
  return [
    (x - camera.cx) * camera.scale + canvas.width / 2,
    canvas.height / 2 - (y - camera.cy) * camera.scale,
  ];
}

function toWorld(px, py) {
  return [
    (px - canvas.width / 2) / camera.scale + camera.cx,
    (canvas.height / 2 - py) / camera.scale + camera.cy,
  ];
}

function eventPixels(event) {
  const r = canvas.getBoundingClientRect();
  return [
    (event.clientX - r.left) * (canvas.width / r.width),
    (event.clientY - r.top) * (canvas.height / r.height),
  ];
}

// --- drawing ----------------------------------------------------------------

const FILL = {
  fixed: '#8a8f98',
  kinematic: '#7a6cc4',
  awake: '#3d7ec9',
  asleep: '#a9c3df',
  frozen: '#d04040',
  player: '#e08a1e',
};

function bodyFill(kind, state, isPlayer) {
  if (isPlayer) return FILL.player;
  if (kind === 0) return FILL.fixed;
  if (state === 2) return FILL.frozen;
  if (kind === 1) return FILL.kinematic;
  return state === 1 ? FILL.asleep : FILL.awake;
}

// A spring: a zigzag of 8 teeth between its ends (a straight line when the
// ends are closer than 2 pixels).
function zigzag(sx, sy, ex, ey) {
  const dx = ex - sx, dy = ey - sy;
  const length = Math.hypot(dx, dy);
  ctx.moveTo(sx, sy);
  if (length < 2) { ctx.lineTo(ex, ey); return; }
  const teeth = 8, width = Math.min(6, length / 3);
  const nx = -dy / length * width, ny = dx / length * width;
  for (let i = 1; i < 2 * teeth; i += 1) {
    const t = i / (2 * teeth), side = i % 2 === 1 ? 1 : -1;
    ctx.lineTo(sx + dx * t + side * nx, sy + dy * t + side * ny);
  }
  ctx.lineTo(ex, ey);
}

function draw() {
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const s = camera.scale;
  const grapple = pg.isGrapple() ? pg.grappleState() : null;
  const bodies = pg.bodies();
  for (let i = 0; i < bodies.length; i += BODY_STRIDE) {
    const [shape, x, y, hx, hy, kind, state] = bodies.subarray(i, i + BODY_STRIDE);
    const isPlayer = grapple !== null && grapple.length >= 2 && x === grapple[0] && y === grapple[1];
    const [px, py] = toScreen(x, y);
    ctx.fillStyle = bodyFill(kind, state, isPlayer);
    ctx.beginPath();
    if (shape === 0) {
      ctx.arc(px, py, Math.max(hx * s, 0.5), 0, 2 * Math.PI);
    } else {
      ctx.rect(px - hx * s, py - hy * s, 2 * hx * s, 2 * hy * s);
    }
    ctx.fill();
    if (state === 1 && s * hx > 3) {
      // Sleeping bodies: outlined, so a resting stack is visibly asleep.
      ctx.strokeStyle = '#5b7fa8';
      ctx.lineWidth = 1;
      ctx.stroke();
    }
  }
  if ($('show-contacts').checked) {
    const c = pg.contacts();
    ctx.strokeStyle = 'rgba(200, 60, 60, 0.6)';
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (let i = 0; i < c.length; i += 4) {
      const [ax, ay] = toScreen(c[i], c[i + 1]);
      const [bx, by] = toScreen(c[i + 2], c[i + 3]);
      ctx.moveTo(ax, ay);
      ctx.lineTo(bx, by);
    }
    ctx.stroke();
  }
  const k = pg.constraints();
  for (let i = 0; i < k.length; i += CONSTRAINT_STRIDE) {
    const [kind, ax, ay, bx, by] = k.subarray(i, i + 5);
    const [sx, sy] = toScreen(ax, ay);
    const [ex, ey] = toScreen(bx, by);
    ctx.strokeStyle = kind === 2 ? '#7a4a1c' : '#2f9a52';
    ctx.lineWidth = kind === 2 ? 2 : 1.5;
    ctx.beginPath();
    if (kind === 2) {
      ctx.moveTo(sx, sy);
      ctx.lineTo(ex, ey);
    } else {
      zigzag(sx, sy, ex, ey);
    }
    ctx.stroke();
    ctx.fillStyle = '#333';
    ctx.fillRect(sx - 2, sy - 2, 4, 4);
  }
  if (grapple !== null && grapple.length >= 2 && mouseWorld !== null && grapple.length < 5) {
    // The aim: where a shot would hit (a ray cast every frame).
    const hit = guard(() => pg.aim(mouseWorld[0], mouseWorld[1]));
    const [px, py] = toScreen(grapple[0], grapple[1]);
    ctx.strokeStyle = 'rgba(224, 138, 30, 0.7)';
    ctx.setLineDash([2, 4]);
    ctx.beginPath();
    ctx.moveTo(px, py);
    if (hit && hit.length === 2) {
      const [hx, hy] = toScreen(hit[0], hit[1]);
      ctx.lineTo(hx, hy);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.strokeStyle = '#e08a1e';
      ctx.beginPath();
      ctx.arc(hx, hy, 5, 0, 2 * Math.PI);
    } else {
      const [mx, my] = toScreen(mouseWorld[0], mouseWorld[1]);
      ctx.lineTo(mx, my);
    }
    ctx.stroke();
    ctx.setLineDash([]);
  }
  if (drag !== null && drag.moved) {
    ctx.strokeStyle = '#c03030';
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(drag.startPx[0], drag.startPx[1]);
    ctx.lineTo(drag.nowPx[0], drag.nowPx[1]);
    ctx.stroke();
  }
}

// --- state readout ----------------------------------------------------------

function msPerStep() {
  if (stepTimes.length === 0) return null;
  return stepTimes.reduce((a, b) => a + b, 0) / stepTimes.length;
}

function updateReadout() {
  const tick = pg.tick();
  const hash = pg.hash();
  $('tick').textContent = String(tick);
  $('hash').textContent = hash;
  const ms = msPerStep();
  $('ms').textContent = ms === null ? '–' : ms.toFixed(3);
  $('bodies').textContent = String(pg.bodyCount());
  $('constraints').textContent = String(pg.constraintCount());
  const expected = native && native.scenes[pg.scene()];
  $('native-scene').textContent = expected || '– (not a CLI scene)';
  if (expected && sceneCheck === null && tick === native.scene_ticks) {
    sceneCheck = hash === expected ? 'equal' : 'different';
  }
  const check = $('scene-check');
  check.className = 'check' + (sceneCheck ? ' ' + sceneCheck : '');
  check.textContent = sceneCheck === null
    ? (expected ? `compared with native at tick ${native.scene_ticks}` : '')
    : `tick ${native.scene_ticks}: ${sceneCheck === 'equal' ? 'same hash as native' : 'DIFFERENT from native'}`;
}

// --- stepping ---------------------------------------------------------------

function stepOnce() {
  if (pg.isGrapple()) {
    pg.setControls(
      keys.has('a') || keys.has('arrowleft'),
      keys.has('d') || keys.has('arrowright'),
      keys.has('w') || keys.has('arrowup'),
      keys.has('s') || keys.has('arrowdown'),
    );
  }
  const t0 = performance.now();
  pg.step();
  const elapsed = performance.now() - t0;
  stepTimes.push(elapsed);
  if (stepTimes.length > TIMING_WINDOW) stepTimes.shift();
  // A scene passing the comparison tick between two frames is still checked.
  if (sceneCheck === null && native && pg.tick() === native.scene_ticks) updateReadout();
  return elapsed;
}

function setPlaying(on) {
  playing = on;
  $('play').textContent = on ? 'pause' : 'play';
}

function loadScene(name) {
  pg = new Playground(name);
  stepTimes = [];
  sceneCheck = null;
  drag = null;
  $('scene').value = name;
  $('help-grapple').hidden = !pg.isGrapple();
  showError('');
  frameScene();
  updateReadout();
}

function loop() {
  if (playing) stepOnce();
  draw();
  updateReadout();
  requestAnimationFrame(loop);
}

// --- input ------------------------------------------------------------------

canvas.addEventListener('mousedown', (event) => {
  canvas.focus();
  const px = eventPixels(event);
  const w = toWorld(px[0], px[1]);
  if (pg.isGrapple()) {
    if (event.button !== 0) return;
    const roped = pg.grappleState().length >= 5;
    guard(() => (roped ? pg.release() : pg.fire(w[0], w[1])));
    return;
  }
  drag = { start: w, startPx: px, nowPx: px, moved: false };
});

canvas.addEventListener('mousemove', (event) => {
  const px = eventPixels(event);
  mouseWorld = toWorld(px[0], px[1]);
  if (drag !== null) {
    drag.nowPx = px;
    drag.moved ||= Math.hypot(px[0] - drag.startPx[0], px[1] - drag.startPx[1]) > CLICK_SLOP;
  }
});

window.addEventListener('mouseup', (event) => {
  if (drag === null) return;
  const d = drag;
  drag = null;
  if (!d.moved) {
    const shape = document.querySelector('input[name="shape"]:checked').value;
    guard(() => pg.dropBody(d.start[0], d.start[1], shape));
  } else {
    const end = toWorld(...eventPixels(event));
    guard(() => pg.push(d.start[0], d.start[1],
      DRAG_GAIN * (end[0] - d.start[0]), DRAG_GAIN * (end[1] - d.start[1])));
  }
});

canvas.addEventListener('contextmenu', (event) => {
  if (pg.isGrapple()) {
    event.preventDefault();
    guard(() => pg.release());
  }
});

window.addEventListener('keydown', (event) => {
  if (event.target instanceof HTMLSelectElement || event.target instanceof HTMLInputElement) return;
  const key = event.key.toLowerCase();
  if (key === ' ') {
    event.preventDefault();
    if (pg.isGrapple()) {
      const roped = pg.grappleState().length >= 5;
      if (roped) guard(() => pg.release());
      else if (mouseWorld !== null) guard(() => pg.fire(mouseWorld[0], mouseWorld[1]));
    } else {
      setPlaying(!playing);
    }
    return;
  }
  if (key === 'n') { stepOnce(); return; }
  if (key.startsWith('arrow')) event.preventDefault();
  keys.add(key);
});
window.addEventListener('keyup', (event) => keys.delete(event.key.toLowerCase()));
window.addEventListener('blur', () => keys.clear());

$('play').addEventListener('click', () => setPlaying(!playing));
$('step').addEventListener('click', () => { setPlaying(false); stepOnce(); });
$('reset').addEventListener('click', () => loadScene(pg.scene()));
$('scene').addEventListener('change', (event) => loadScene(event.target.value));

// --- determinism panel --------------------------------------------------------

function runDeterminism() {
  const d = native.determinism;
  $('det-what').textContent =
    `${d.ticks} ticks of "${d.scene}" with the scripted input of seed ${d.seed} ` +
    '(spawns, despawns, impulses, velocities, wakes, a refused command)';
  const t0 = performance.now();
  const browser = determinismHash(d.scene, d.seed, d.ticks);
  const ms = performance.now() - t0;
  $('det-browser').textContent = browser;
  $('det-native').textContent = d.hash;
  const equal = browser === d.hash;
  const verdict = $('det-verdict');
  verdict.className = 'check ' + (equal ? 'equal' : 'different');
  verdict.textContent = (equal ? 'equal' : 'DIFFERENT') + ` (replayed in ${ms.toFixed(0)} ms)`;
  return { browser, native: d.hash, equal, ms };
}
$('det-run').addEventListener('click', runDeterminism);

// --- start --------------------------------------------------------------------

async function start() {
  await init();
  const response = await fetch('native.json');
  if (!response.ok) throw new Error(`native.json: HTTP ${response.status} (run web/build.sh)`);
  native = await response.json();
  $('native-ticks').textContent = String(native.scene_ticks);
  for (const name of sceneNames()) {
    const option = document.createElement('option');
    option.value = option.textContent = name;
    $('scene').append(option);
  }
  const wanted = new URLSearchParams(location.search).get('scene');
  loadScene(wanted && sceneNames().includes(wanted) ? wanted : 'mixed');
  runDeterminism();
  if (new URLSearchParams(location.search).get('paused') === '1') setPlaying(false);
  requestAnimationFrame(loop);
}

// What the browser test (web/test/) drives besides real mouse and keys: the
// same functions the buttons call, and bulk stepping.
window.clockwork = {
  ready: start(),
  scenes: () => sceneNames(),
  select: (name) => { loadScene(name); return window.clockwork.state(); },
  pause: () => setPlaying(false),
  play: () => setPlaying(true),
  step: (n) => {
    let ms = 0;
    for (let i = 0; i < n; i += 1) ms += stepOnce();
    updateReadout();
    return { ...window.clockwork.state(), msPerStep: n > 0 ? ms / n : 0 };
  },
  bodies: () => Array.from(pg.bodies()),
  state: () => ({
    scene: pg.scene(),
    tick: pg.tick(),
    hash: pg.hash(),
    bodies: pg.bodyCount(),
    constraints: pg.constraintCount(),
    grapple: Array.from(pg.grappleState()),
    sceneCheck,
  }),
  toPage: (x, y) => {
    const [px, py] = toScreen(x, y);
    const r = canvas.getBoundingClientRect();
    return [r.left + px * (r.width / canvas.width), r.top + py * (r.height / canvas.height)];
  },
  native: () => native,
  runDeterminism,
};
window.clockwork.ready.catch((e) => {
  showError(String(e));
  console.error(e);
});
