// The script of bpde's view.html (io/html_view.h): bundled with three.js and OrbitControls into one
// classic script at build time (CMakeLists.txt, esbuild), so that the page opens from disk.
//
// The page's data is the JSON object in <script id="bpde-data" type="application/json">:
//   vertices, triangles: counts; positions (3 per vertex), normals (3 per vertex), H (1 per
//   vertex): base64 little-endian float32; regular: base64 uint8 (1 per vertex); indices: base64
//   uint32 (3 per triangle); net: {points: base64 float32 (3 per point), lines: base64 uint32
//   (2 per segment)}; range: [lo, hi] of the colour scale; report: the report object.
//   A patch complex adds seams: {edges, interior, samples: counts; points: base64 float32 (3 per
//   point), lines: base64 uint32 (2 per segment)}, the patch edges as polylines (shared edges once),
//   shown with the check box #bpde-show-seams; its net is every patch's control net.
// After the first frame the page writes what it drew into #bpde-status (data-vertices,
// data-triangles, data-drawn: non-background pixels in the middle of the canvas) and the title.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

function bytes(b64) {
  const s = atob(b64);
  const out = new Uint8Array(s.length);
  for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
  return out;
}
const f32 = (b64) => new Float32Array(bytes(b64).buffer);
const u32 = (b64) => new Uint32Array(bytes(b64).buffer);

// A perceptual blue-white-red scale would hide the sign convention; use viridis-like stops.
const STOPS = [
  [0.267, 0.005, 0.329], [0.283, 0.141, 0.458], [0.254, 0.265, 0.530], [0.207, 0.372, 0.553],
  [0.164, 0.471, 0.558], [0.128, 0.567, 0.551], [0.135, 0.659, 0.518], [0.267, 0.749, 0.441],
  [0.478, 0.821, 0.318], [0.741, 0.873, 0.150], [0.993, 0.906, 0.144],
];
function colour(t) {
  const x = Math.min(1, Math.max(0, t)) * (STOPS.length - 1);
  const i = Math.min(STOPS.length - 2, Math.floor(x)), f = x - i;
  return STOPS[i].map((a, k) => a + f * (STOPS[i + 1][k] - a));
}

function formatNumber(v) {
  if (typeof v !== 'number') return String(v);
  if (Number.isInteger(v)) return String(v);
  return Math.abs(v) >= 1e-3 && Math.abs(v) < 1e6 ? v.toPrecision(8) : v.toExponential(6);
}

// A number in `digits` significant digits, without trailing zeros (the list tables, the legend).
function shortNumber(v, digits) {
  if (typeof v !== 'number') return v === null ? '' : String(v);
  if (Number.isInteger(v) && Math.abs(v) < 1e9) return String(v);
  const a = Math.abs(v);
  const text = a >= 1e-3 && a < 1e6 ? v.toPrecision(digits) : v.toExponential(digits - 1);
  return text.replace(/(\.\d*?)0+(e|$)/, '$1$2').replace(/\.(e|$)/, '$1');
}

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const isListOfObjects = (v) => Array.isArray(v) && v.length > 0 && v.every(isObject);

// A scalar, an array of scalars or an object as one line of text.
function valueText(v) {
  if (Array.isArray(v)) return '[' + v.map((x) => (isObject(x) || Array.isArray(x) ? JSON.stringify(x) : formatNumber(x))).join(', ') + ']';
  if (isObject(v)) return Object.keys(v).length ? JSON.stringify(v) : '–';
  if (v === null) return '–';
  return formatNumber(v);
}

// A field name that may break after its underscores and dots.
function breakableName(cell, name) {
  name.split(/(?<=[_.])/).forEach((part, i) => {
    if (i) cell.append(document.createElement('wbr'));
    cell.append(part);
  });
}

// A list of objects (such as boundary_fit or routes) as a small table. Nested objects are
// flattened one level (key.field) and fields null in every object are left out. Up to
// LIST_COLUMNS objects: one column per object, headed by the object's name (its first field whose
// of NAME_FIELDS whose values are distinct numbers or strings) or its index, the fields down
// the side; longer lists: one row per object, one column per field, long values cut with an
// ellipsis (whole on hover). The table's data-layout says which ("columns" or "rows").
const LIST_COLUMNS = 4;
const NAME_FIELDS = ['name', 'route', 'edge', 'job', 'id'];
function listTable(key, list) {
  const objects = list.map((o) => {
    const flat = {};
    for (const [k, v] of Object.entries(o)) {
      if (isObject(v) && Object.keys(v).length) for (const [k2, v2] of Object.entries(v)) flat[k + '.' + k2] = v2;
      else flat[k] = v;
    }
    return flat;
  });
  const present = (v) => v !== null && v !== undefined && !(isObject(v) && !Object.keys(v).length);
  const fields = [];
  for (const o of objects)
    for (const k of Object.keys(o))
      if (!fields.includes(k) && objects.some((x) => present(x[k]))) fields.push(k);
  const cell = (tag, text, title) => {
    const c = document.createElement(tag);
    c.textContent = text;
    c.title = title;
    return c;
  };
  const short = (v) => (typeof v === 'number' ? shortNumber(v, 4) : v === undefined ? '' : valueText(v));
  const full = (v) => (v === undefined ? '' : valueText(v));

  const box = document.createElement('div');
  box.className = 'bpde-list';
  box.append(cell('div', `${key} (${list.length})`, key));
  box.firstChild.className = 'bpde-caption';
  const table = document.createElement('table');
  table.className = 'bpde-list-table';
  table.dataset.key = key;
  const head = document.createElement('tr');
  if (objects.length <= LIST_COLUMNS) {
    table.dataset.layout = 'columns';
    const scalar = (v) => typeof v === 'string' || typeof v === 'number';
    const name = NAME_FIELDS.find(
        (k) => objects.every((o) => scalar(o[k])) && new Set(objects.map((o) => o[k])).size === objects.length);
    const corner = document.createElement('th');
    breakableName(corner, name ?? '#');
    head.append(corner);
    objects.forEach((o, i) => head.append(cell('th', name ? String(o[name]) : String(i), name ? `${name}: ${o[name]}` : '')));
    table.append(head);
    for (const k of fields) {
      if (k === name) continue;
      const tr = document.createElement('tr');
      const th = document.createElement('th');
      breakableName(th, k);
      tr.append(th);
      for (const o of objects) tr.append(cell('td', short(o[k]), `${k}: ${full(o[k])}`));
      table.append(tr);
    }
  } else {
    table.dataset.layout = 'rows';
    for (const k of fields) {
      const th = document.createElement('th');
      breakableName(th, k);
      th.title = k;
      head.append(th);
    }
    table.append(head);
    for (const o of objects) {
      const tr = document.createElement('tr');
      for (const k of fields) tr.append(cell('td', short(o[k]), `${k}: ${full(o[k])}`));
      table.append(tr);
    }
  }
  box.append(table);
  return box;
}

// The report beside the surface: its scalars (and the fields of its objects, as key.field) in
// one two-column table, then each list of objects as its own table below it. Values longer than
// LONG_VALUE characters (a list of points) are cut there, whole on hover.
const LONG_VALUE = 240;
function reportTable(report) {
  const table = document.getElementById('bpde-report');
  const lists = document.getElementById('bpde-lists');
  const row = (k, v) => {
    const tr = document.createElement('tr');
    const a = document.createElement('th'), b = document.createElement('td');
    breakableName(a, k);
    b.textContent = v.length > LONG_VALUE ? v.slice(0, LONG_VALUE) + '…' : v;
    b.title = v;
    tr.append(a, b);
    table.append(tr);
  };
  const entry = (k, v) => {
    if (isListOfObjects(v)) lists.append(listTable(k, v));
    else row(k, valueText(v));
  };
  for (const [k, v] of Object.entries(report)) {
    if (isObject(v) && Object.keys(v).length) {
      for (const [k2, v2] of Object.entries(v)) entry(k + '.' + k2, v2);
    } else {
      entry(k, v);
    }
  }
}

// The colour bar, vertical (hi at the top), with LEGEND_TICKS evenly spaced values; each tick's
// label carries its exact value in data-value.
const LEGEND_TICKS = 5;
function legend(lo, hi) {
  const c = document.getElementById('bpde-legend');
  const g = c.getContext('2d');
  for (let y = 0; y < c.height; ++y) {
    const [r, gr, b] = colour(1 - y / (c.height - 1));
    g.fillStyle = `rgb(${255 * r},${255 * gr},${255 * b})`;
    g.fillRect(0, y, c.width, 1);
  }
  const ticks = document.getElementById('bpde-ticks');
  const step = (hi - lo) / (LEGEND_TICKS - 1);
  const scale = Math.max(Math.abs(lo), Math.abs(hi));
  // enough digits that neighbouring ticks differ
  const digits = Math.min(10, Math.max(3, Math.ceil(Math.log10(step > 0 ? scale / step : 1)) + 2));
  for (let k = 0; k < LEGEND_TICKS; ++k) {
    let v = k === LEGEND_TICKS - 1 ? hi : lo + k * step;
    if (Math.abs(v) < 1e-9 * Math.abs(step)) v = 0;
    const tick = document.createElement('div');
    tick.className = 'bpde-tick';
    tick.dataset.value = String(v);
    tick.style.top = `${100 * (1 - k / (LEGEND_TICKS - 1))}%`;
    tick.textContent = shortNumber(v, digits);
    ticks.append(tick);
  }
}

function main() {
  const data = JSON.parse(document.getElementById('bpde-data').textContent);
  const canvas = document.getElementById('bpde-canvas');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const background = new THREE.Color(0xffffff);
  renderer.setClearColor(background, 1);
  const scene = new THREE.Scene();

  const positions = f32(data.positions), normals = f32(data.normals), H = f32(data.H);
  const [lo, hi] = data.range;
  const colours = new Float32Array(3 * data.vertices);
  for (let k = 0; k < data.vertices; ++k) colours.set(colour(hi > lo ? (H[k] - lo) / (hi - lo) : 0.5), 3 * k);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  geometry.setIndex(new THREE.BufferAttribute(u32(data.indices), 1));
  geometry.computeBoundingSphere();
  const surface = new THREE.Mesh(
    geometry,
    new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide, polygonOffset: true,
                                    polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
  scene.add(surface);
  const wire = new THREE.Mesh(geometry,
                              new THREE.MeshBasicMaterial({ color: 0x202020, wireframe: true, transparent: true, opacity: 0.35 }));
  wire.visible = false;
  scene.add(wire);

  const netGeometry = new THREE.BufferGeometry();
  netGeometry.setAttribute('position', new THREE.BufferAttribute(f32(data.net.points), 3));
  netGeometry.setIndex(new THREE.BufferAttribute(u32(data.net.lines), 1));
  const net = new THREE.Group();
  net.add(new THREE.LineSegments(netGeometry, new THREE.LineBasicMaterial({ color: 0xc03020 })));
  net.add(new THREE.Points(netGeometry, new THREE.PointsMaterial({ color: 0xc03020, size: 6, sizeAttenuation: false })));
  scene.add(net);

  const toggles = [['bpde-show-net', net], ['bpde-show-wire', wire]];
  if (data.seams) {
    const seamGeometry = new THREE.BufferGeometry();
    seamGeometry.setAttribute('position', new THREE.BufferAttribute(f32(data.seams.points), 3));
    seamGeometry.setIndex(new THREE.BufferAttribute(u32(data.seams.lines), 1));
    const seams = new THREE.LineSegments(seamGeometry, new THREE.LineBasicMaterial({ color: 0x1040c0 }));
    scene.add(seams);
    toggles.push(['bpde-show-seams', seams]);
    document.getElementById('bpde-seams-label').hidden = false;
  }

  scene.add(new THREE.AmbientLight(0xffffff, 1.2));
  const camera = new THREE.PerspectiveCamera(35, 1, 1e-3, 1e3);
  const head = new THREE.DirectionalLight(0xffffff, 1.8);
  camera.add(head);
  scene.add(camera);

  // frame the surface and its net, looking down on it from +z and a little from the side
  netGeometry.computeBoundingSphere();
  const sphere = geometry.boundingSphere.clone().union(netGeometry.boundingSphere);
  const r = Math.max(sphere.radius, 1e-9);
  camera.near = r / 100;
  camera.far = r * 100;
  camera.position.copy(sphere.center).add(new THREE.Vector3(0.9, -1.6, 2.6).normalize().multiplyScalar(4.2 * r));
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(sphere.center);

  const resize = () => {
    const w = canvas.clientWidth || 640, h = canvas.clientHeight || 480;
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  };
  const render = () => renderer.render(scene, camera);
  resize();
  controls.update();
  controls.addEventListener('change', render);
  window.addEventListener('resize', () => { resize(); render(); });
  for (const [id, object] of toggles) {
    const box = document.getElementById(id);
    object.visible = box.checked;
    box.addEventListener('change', () => { object.visible = box.checked; render(); });
  }
  render();

  // what was drawn: non-background pixels in the middle third of the canvas
  const gl = renderer.getContext();
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const x0 = Math.floor(w / 3), y0 = Math.floor(h / 3), cw = Math.floor(w / 3), ch = Math.floor(h / 3);
  const pixels = new Uint8Array(4 * cw * ch);
  gl.readPixels(x0, y0, cw, ch, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let drawn = 0;
  for (let k = 0; k < cw * ch; ++k)
    if (Math.abs(pixels[4 * k] - 255) + Math.abs(pixels[4 * k + 1] - 255) + Math.abs(pixels[4 * k + 2] - 255) > 24) ++drawn;
  const status = document.getElementById('bpde-status');
  status.dataset.vertices = String(data.vertices);
  status.dataset.triangles = String(data.triangles);
  status.dataset.drawn = String(drawn);
  status.dataset.sampled = String(cw * ch);
  status.textContent = `${data.vertices} vertices, ${data.triangles} triangles`;
  document.title = `${data.title} (${data.vertices} vertices)`;

  legend(lo, hi);
  reportTable(data.report);
}

try {
  main();
} catch (e) {
  const status = document.getElementById('bpde-status');
  status.dataset.error = String(e);
  status.textContent = 'viewer error: ' + e;
  document.title = 'bpde view: error';
}
