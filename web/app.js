// The page: a mechanism of the library (or the text in the editor) read by
// linkage compiled to WebAssembly; its pose at the driver's value drawn by
// the library's own pictures, its numbers in a table, the file's mistakes
// listed where they are. `?selftest` records what a test reads in the DOM.
import init, { Mechanism, importPylinkage, importPyslvs, library, mistakes, withParameters } from "./pkg/linkage_web.js";

const $ = (id) => document.getElementById(id);
let mechanism = null;
let drive = null;
let info = null;
let sweep = null;
// Where a link pinned to the frame or a block on a fixed guide comes to
// rest over the drive range: found when the dimensions change, drawn
// faint at every redraw.
let deadCentres = [];
// The pivot being dragged, if one is.
let dragging = null;
let current = 0;
// Where the picture puts the model (for a click read as a point).
let placement = null;
// The parameters as the editor's text gives them.
let written = [];

function status(text, error = false) {
  $("status").textContent = text;
  $("status").className = error ? "error" : "";
}

// The plotted coordinate against the driver over the sweep, the singular
// poses met and the dead centres marked, the current pose as a cursor.
function plot() {
  if (!sweep || sweep.v.length < 2) { $("plot").innerHTML = ""; return; }
  // "u:k", "udot:k", "uddot:k" (coordinate k and its rates), "point:j"
  // (coordinate j of the points' x, y in turn) or "transmission".
  const [series, index] = $("quantity").value.split(":");
  const k = Number(index ?? 0);
  const m = info.uNames.length;
  const xs = sweep.v;
  const p = info.pointNames.length;
  const ys = series === "transmission"
    ? sweep.transmission.map((a) => a * 180 / Math.PI)
    : series === "point"
      ? xs.map((_, i) => sweep.points[i * 2 * p + k])
      : xs.map((_, i) => sweep[series][i * m + k]);
  const label = $("quantity").selectedOptions[0].textContent;
  const [w, h, pad] = [640, 200, 40];
  const [x0, x1] = [Math.min(...xs), Math.max(...xs)];
  let [y0, y1] = [Math.min(...ys), Math.max(...ys)];
  if (y1 - y0 < 1e-12) { y0 -= 1; y1 += 1; }
  const X = (x) => pad + (w - 2 * pad) * (x - x0) / (x1 - x0 || 1);
  const Y = (y) => h - pad + (2 * pad - h) * (y - y0) / (y1 - y0);
  const path = xs.map((x, i) => `${i ? "L" : "M"}${X(x).toFixed(2)},${Y(ys[i]).toFixed(2)}`).join("");
  // On the curve where it plots the pose's own value, else on the axis.
  const at = (e) => series === "u" ? Y(e.u[k])
    : series === "point" ? Y(e.points[Math.floor(k / 2)][k % 2]) : h - pad;
  const marks = sweep.events.map((e) =>
    `<circle class="singular" cx="${X(e.v[0]).toFixed(2)}" cy="${at(e).toFixed(2)}" r="4" fill="#a00"><title>${e.kind}</title></circle>`);
  const rests = deadCentres.map((d) => {
    const [x, y] = [X(d.v[0]), at(d)];
    return `<path class="dead-centre" d="M${x.toFixed(2)},${(y - 5).toFixed(2)}l5,5l-5,5l-5,-5z" fill="#d35400">` +
      `<title>dead centre: ${d.what} at rest</title></path>`;
  });
  const fmt = (x) => Number(x.toPrecision(4));
  $("plot").innerHTML =
    `<svg viewBox="0 0 ${w} ${h}" xmlns="http://www.w3.org/2000/svg" font-size="12" font-family="sans-serif">` +
    `<rect x="${pad}" y="${pad / 2}" width="${w - 2 * pad}" height="${h - 1.5 * pad}" fill="none" stroke="#ccc"/>` +
    (y0 < 0 && y1 > 0 ? `<line class="zero" x1="${pad}" x2="${w - pad}" y1="${Y(0).toFixed(2)}" y2="${Y(0).toFixed(2)}" stroke="#bbb"/>` +
      // Its label only clear of the range's own.
      (Math.min(Y(y0) - Y(0), Y(0) - Y(y1)) > 14
        ? `<text x="${pad - 4}" y="${(Y(0) + 4).toFixed(2)}" text-anchor="end" fill="#888">0</text>` : "") : "") +
    `<path d="${path}" fill="none" stroke="#345" stroke-width="1.5"/>${marks.join("")}${rests.join("")}` +
    `<line id="cursor" x1="${X(current)}" x2="${X(current)}" y1="${pad / 2}" y2="${h - pad}" stroke="#07c" stroke-dasharray="4 3"/>` +
    `<text x="${pad}" y="${h - pad / 3}">${fmt(x0)}</text><text x="${w - pad}" y="${h - pad / 3}" text-anchor="end">${fmt(x1)} ${info.vNames[0]}</text>` +
    `<text x="4" y="${Y(y1) + 4}">${fmt(y1)}</text><text x="4" y="${Y(y0) + 4}">${fmt(y0)}</text>` +
    `<text x="${w / 2}" y="14" text-anchor="middle">${label} against ${info.vNames[0]}</text></svg>`;
  document.body.dataset.plotted = `${xs.length} ${sweep.events.length}`;
  const listed = [
    ...sweep.events.map((e) => ({ v: e.v[0], text: e.kind })),
    ...deadCentres.map((d) => ({ v: d.v[0], text: `dead centre: ${d.what} at rest` })),
  ].sort((a, b) => a.v - b.v);
  $("events").innerHTML = listed.map((e) =>
    `<li>${e.text} at ${info.vNames[0]} = ${e.v.toPrecision(12)}</li>`).join("") +
    (sweep.complete ? "" : "<li>the sweep stops before the end of the drive range</li>");
}

function draw(value) {
  if (!mechanism) return;
  current = value;
  // The slider moves the first driver; any other stays at its `at`.
  const v = [value, ...drive.at.slice(1)];
  $("driver-value").textContent = `${info.vNames[0]} = ${v[0].toFixed(6)}`;
  try {
    const started = performance.now();
    const pose = JSON.parse(mechanism.analyze(v));
    const picture = JSON.parse(mechanism.picture(640, v, JSON.stringify(targets()), JSON.stringify(deadCentres),
      $("vectors").value));
    $("picture").innerHTML = picture.svg;
    placement = picture.placement;
    const took = performance.now() - started;
    const rows = info.uNames.map((n, k) =>
      `<tr><th scope="row">${n}</th><td>${pose.u[k].toPrecision(10)}</td>` +
      `<td>${pose.udot[k].toPrecision(8)}</td><td>${pose.uddot[k].toPrecision(8)}</td></tr>`);
    $("pose").innerHTML = "<tr><th></th><th>value</th><th>velocity</th><th>acceleration</th></tr>" + rows.join("");
    status(took > 0 ? `pose and picture in ${took.toFixed(1)} ms` : "pose and picture drawn");
    showSensitivities(v);
    const cursor = document.getElementById("cursor");
    if (cursor) plot();
    document.body.dataset.pose = JSON.stringify(pose);
  } catch (e) {
    status(e.message, true);
    document.body.dataset.error = e.message;
  }
}

function resweep() {
  try {
    sweep = JSON.parse(mechanism.sweep(0));
  } catch (e) {
    sweep = null;
    $("events").innerHTML = `<li>${e.message}</li>`;
  }
  // While a pivot is dragged, none (found again when it is let go).
  try {
    deadCentres = sweep && !dragging ? JSON.parse(mechanism.deadCentres()) : [];
  } catch (e) {
    deadCentres = [];
  }
  plot();
}

const escaped = (text) => text.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
// The mistakes underlined in the editor itself: the layer behind it holds
// the same text (the editor's own is drawn over it), each mistake's range
// in a mark; a mistake at a line's end marks a space there.
function underline(text, found) {
  const ranges = found.filter((m) => m.from !== null).map((m) => [m.from, m.to]).sort((a, b) => a[0] - b[0]);
  let html = "";
  let at = 0;
  for (const [from, to] of ranges) {
    if (from < at) continue;
    html += escaped(text.slice(at, from));
    const marked = text.slice(from, Math.max(to, from)).replace(/\n[^]*$/, "");
    if (marked === "") {
      html += "<mark> </mark>";
      at = from;
    } else {
      html += `<mark>${escaped(marked)}</mark>`;
      at = from + marked.length;
    }
  }
  // A last line, so that the layer scrolls as far as the editor.
  $("editor-marks").innerHTML = html + escaped(text.slice(at)) + "\n ";
  followScroll();
}
function followScroll() {
  $("editor-marks").scrollTop = $("editor").scrollTop;
  $("editor-marks").scrollLeft = $("editor").scrollLeft;
}

function showMistakes(text) {
  const found = JSON.parse(mistakes(text, "the editor"));
  underline(text, found);
  const list = $("mistakes");
  list.innerHTML = "";
  for (const m of found) {
    const item = document.createElement("li");
    item.textContent = m.message;
    item.tabIndex = 0;
    const select = () => {
      if (m.from !== null) {
        $("editor").focus();
        $("editor").setSelectionRange(m.from, m.to);
      }
    };
    item.addEventListener("click", select);
    item.addEventListener("keydown", (e) => { if (e.key === "Enter") select(); });
    list.appendChild(item);
  }
  document.body.dataset.mistakes = String(found.length);
  return found.length === 0;
}

function open(text) {
  if (!showMistakes(text)) {
    mechanism = null;
    status("the file has mistakes (listed beside it)", true);
    return;
  }
  try {
    mechanism = Mechanism.fromText(text, "the editor");
    info = JSON.parse(mechanism.info());
    written = [...info.parameters];
    drive = JSON.parse(mechanism.analyze([])).drive;
    const [low, high] = [Math.min(drive.from[0], drive.to[0]), Math.max(drive.from[0], drive.to[0])];
    $("driver").min = String(low);
    $("driver").max = String(high);
    $("driver").step = String((high - low) / Math.max(drive.steps, 1) / 10);
    $("driver").value = String(drive.at[0]);
    $("driver-label").textContent = info.vNames[0];
    // A file that draws no arrow (a mechanism given by joints and links)
    // is shown with its points' velocities.
    $("vectors").value = info.fileArrows > 0 ? "file" : "velocities";
    $("quantity").innerHTML = [
      ...info.uNames.map((n, k) => `<option value="u:${k}">${n}</option>`),
      ...info.uNames.map((n, k) => `<option value="udot:${k}">${n}' (velocity)</option>`),
      ...info.uNames.map((n, k) => `<option value="uddot:${k}">${n}'' (acceleration)</option>`),
      ...info.pointNames.flatMap((n, c) => [`<option value="point:${2 * c}">${n}.x</option>`,
        `<option value="point:${2 * c + 1}">${n}.y</option>`]),
      `<option value="transmission">transmission angle (deg)</option>`,
    ].join("");
    resweep();
    dimensionsPanel();
    designPanel();
    draw(drive.at[0]);
    plot();
  } catch (e) {
    mechanism = null;
    status(e.message, true);
    document.body.dataset.error = e.message;
  }
}

await init();
const files = JSON.parse(library());
for (const f of files) {
  const option = document.createElement("option");
  option.value = f.path;
  option.textContent = f.path;
  $("library").appendChild(option);
}
$("library").addEventListener("change", () => {
  const f = files.find((x) => x.path === $("library").value);
  $("editor").value = f.text;
  open(f.text);
});
let typing = null;
$("editor").addEventListener("input", () => {
  clearTimeout(typing);
  typing = setTimeout(() => open($("editor").value), 300);
});
$("editor").addEventListener("scroll", followScroll);
$("driver").addEventListener("input", () => draw(Number($("driver").value)));
$("quantity").addEventListener("change", plot);
$("vectors").addEventListener("change", () => draw(current));

// The dimensions: each parameter's value, edited in place; and the exact
// sensitivities of the pose at the driver's value.
function dimensionsPanel() {
  $("dimensions").innerHTML = info.parameterNames.map((n, k) =>
    `<tr><td><label for="dim-${k}">${n}</label></td>` +
    `<td><input type="number" step="any" id="dim-${k}" value="${info.parameters[k]}"></td></tr>`).join("");
  info.parameterNames.forEach((n, k) => {
    $(`dim-${k}`).addEventListener("change", () => setDimension(n, Number($(`dim-${k}`).value)));
  });
}
// The editor's text given the parameters the page now uses (a design's,
// edited dimensions), each written where it stood; a topology file keeps
// its text (its parameters come from its joints), and says so.
function writeParameters() {
  const changed = info.parameterNames.flatMap((n, k) =>
    info.parameters[k] !== written[k] ? [[n, info.parameters[k]]] : []);
  if (changed.length === 0) return true;
  try {
    $("editor").value = withParameters($("editor").value, JSON.stringify(changed));
    written = [...info.parameters];
    return true;
  } catch (e) {
    status(`the page uses new values, which the text does not hold: ${e.message}`, true);
    return false;
  }
}
function setDimension(name, value) {
  try {
    mechanism.setParameter(name, value);
  } catch (e) {
    status(`${name}: ${e.message}`, true);
    document.body.dataset.dimensionRefused = e.message;
    return false;
  }
  info = JSON.parse(mechanism.info());
  const k = info.parameterNames.indexOf(name);
  if (k >= 0 && $(`dim-${k}`) && document.activeElement !== $(`dim-${k}`)) $(`dim-${k}`).value = String(value);
  resweep();
  draw(current);
  if (!dragging) writeParameters();
  return true;
}
function showSensitivities(v) {
  let s;
  try {
    s = JSON.parse(mechanism.sensitivities(v));
  } catch (e) {
    $("sensitivities").innerHTML = `<tr><td>${e.message}</td></tr>`;
    return;
  }
  const head = `<tr><th></th>${s.parameters.map((p) => `<th scope="col">∂/∂${p}</th>`).join("")}</tr>`;
  const rows = info.uNames.map((n, i) =>
    `<tr><th scope="row">${n}</th>${s.u[i].map((x) => `<td>${x.toPrecision(6)}</td>`).join("")}</tr>`);
  $("sensitivities").innerHTML = head + rows.join("");
  document.body.dataset.sensitivities = JSON.stringify(s.u);
}
// A ground pivot J of a mechanism given by joints and links is the
// parameters x_J and y_J: dragged on the picture, it moves them (the
// drag in `dragging`, declared above).
function pivotNear(event) {
  const svg = $("picture").querySelector("svg");
  if (!svg || !placement) return null;
  const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(svg.getScreenCTM().inverse());
  const px = (k) => info.parameters[info.parameterNames.indexOf(k)];
  for (const name of info.parameterNames) {
    if (!name.startsWith("x_") || !info.parameterNames.includes(`y_${name.slice(2)}`)) continue;
    const [x, y] = [px(name), px(`y_${name.slice(2)}`)];
    const sx = (x - placement.origin[0]) * placement.scale;
    const sy = placement.top + (placement.origin[1] - y) * placement.scale;
    if (Math.hypot(sx - p.x, sy - p.y) < 12) return name.slice(2);
  }
  return null;
}
// The model point under the pointer, by the picture's map to the screen
// and to the model taken when the drag began (the picture redrawn under
// the pointer may be scaled anew: the pivot follows the pointer).
function modelAt(event, map) {
  const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(map.screen);
  const placed = map.placement;
  return [placed.origin[0] + p.x / placed.scale, placed.origin[1] - (p.y - placed.top) / placed.scale];
}
$("picture").addEventListener("pointerdown", (event) => {
  const joint = mechanism && pivotNear(event);
  if (!joint) return;
  const svg = $("picture").querySelector("svg");
  dragging = { joint, map: { placement: { ...placement }, screen: svg.getScreenCTM().inverse() } };
  $("picture").classList.add("dragging");
  $("picture").setPointerCapture(event.pointerId);
  event.preventDefault();
});
$("picture").addEventListener("pointermove", (event) => {
  if (!dragging) return;
  const [x, y] = modelAt(event, dragging.map);
  mechanism.setParameter(`x_${dragging.joint}`, x);
  if (!setDimension(`y_${dragging.joint}`, y)) return;
  document.body.dataset.dragged = `${dragging.joint} ${x} ${y}`;
});
// A drag ends in a click, which places no target.
let dragged = false;
const endDrag = () => {
  dragged = dragging !== null;
  if (dragged) writeParameters();
  dragging = null;
  if (dragged) { resweep(); draw(current); }
  $("picture").classList.remove("dragging");
};
$("picture").addEventListener("pointerup", endDrag);
$("picture").addEventListener("pointercancel", endDrag);

// The design panel: targets typed or clicked, the free parameters with
// their bounds, a search in a worker with its progress, the certified
// designs to browse and use.
// The targets typed (a line "x, y" each): the points read, and the first
// line that is not two finite numbers, if any.
function readTargets() {
  const lines = $("design-targets").value.split("\n").map((l) => l.trim()).filter((l) => l);
  const points = [];
  for (const [k, line] of lines.entries()) {
    const xy = line.split(/[,\s]+/).map(Number);
    if (xy.length !== 2 || !xy.every(Number.isFinite)) {
      return { points, error: `target line ${k + 1} is not two finite numbers x, y: "${line}"` };
    }
    points.push(xy);
  }
  return { points, error: null };
}
const targets = () => readTargets().points;
function designPanel() {
  $("design-point").innerHTML = info.pointNames.map((n) => `<option>${n}</option>`).join("");
  const last = info.pointNames[info.pointNames.length - 1];
  if (last) $("design-point").value = last;
  freeBounds();
  $("designs").innerHTML = "";
  $("design-status").textContent = "";
}
// Each parameter free by default, within its value ± the larger of its
// size and the targets' extent.
function freeBounds() {
  const t = targets();
  const xs = t.map((p) => p[0]), ys = t.map((p) => p[1]);
  const extent = t.length > 1 ? Math.hypot(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys)) : 1;
  $("design-free-table").innerHTML = info.parameterNames.map((n, k) => {
    const value = info.parameters[k];
    const reach = Math.max(Math.abs(value), extent);
    const fmt = (x) => Number(x.toPrecision(6));
    return `<tr><td><input type="checkbox" id="free-${k}" checked aria-label="${n} free"></td>` +
      `<td><label for="free-${k}">${n}</label></td>` +
      `<td><input type="number" id="lower-${k}" value="${fmt(value - reach)}" aria-label="${n}'s lower bound"></td>` +
      `<td><input type="number" id="upper-${k}" value="${fmt(value + reach)}" aria-label="${n}'s upper bound"></td></tr>`;
  }).join("");
}
function task() {
  const free = info.parameterNames.flatMap((n, k) => $(`free-${k}`).checked
    ? [[n, Number($(`lower-${k}`).value), Number($(`upper-${k}`).value)]] : []);
  const angle = $("design-transmission").value;
  return { point: $("design-point").value, targets: targets(), free, seed: 1,
    minTransmission: angle === "" ? null : Number(angle) };
}
let worker = null;
let watchdog = null;
let found = null;
let chosen = -1;
// What the search was asked (the text, the point, the targets), and the
// designs' small pictures made so far, by their parameters.
let searched = null;
// When each report of the search arrived (the page's clock, ms).
let progressTimes = [];
const thumbnails = new Map();
// The first designs are drawn small; the others are listed.
const DRAWN_DESIGNS = 12;
// A design's path of the searched point over the turn, through the
// targets (dots): a small picture, scaled to fit both.
function thumbnail(d) {
  const key = JSON.stringify(d.parameters);
  if (thumbnails.has(key)) return thumbnails.get(key);
  let svg = "";
  try {
    const m = Mechanism.fromText(searched.text, "the design");
    for (const [name, value] of Object.entries(d.parameters)) m.setParameter(name, value);
    const s = JSON.parse(m.sweep(0));
    const names = JSON.parse(m.info()).pointNames;
    m.free();
    const [j, p] = [names.indexOf(searched.point), names.length];
    const path = s.v.map((_, i) => [s.points[i * 2 * p + 2 * j], s.points[i * 2 * p + 2 * j + 1]]);
    const all = [...path, ...searched.targets];
    const [x0, x1] = [Math.min(...all.map((q) => q[0])), Math.max(...all.map((q) => q[0]))];
    const [y0, y1] = [Math.min(...all.map((q) => q[1])), Math.max(...all.map((q) => q[1]))];
    const [w, h, pad] = [120, 80, 6];
    const scale = Math.min((w - 2 * pad) / (x1 - x0 || 1), (h - 2 * pad) / (y1 - y0 || 1));
    const X = (x) => (pad + (x - x0) * scale).toFixed(1);
    const Y = (y) => (h - pad - (y - y0) * scale).toFixed(1);
    const line = path.map((q, i) => `${i ? "L" : "M"}${X(q[0])},${Y(q[1])}`).join("");
    const dots = searched.targets.map((q) => `<circle cx="${X(q[0])}" cy="${Y(q[1])}" r="2.5" fill="#c0392b"/>`);
    svg = `<svg class="design-path" viewBox="0 0 ${w} ${h}" width="${w}" height="${h}" role="img" ` +
      `aria-label="the design's path of ${searched.point} through the targets" xmlns="http://www.w3.org/2000/svg">` +
      `<path d="${line}" fill="none" stroke="#345" stroke-width="1.2"/>${dots.join("")}</svg>`;
  } catch (e) {
    svg = "";
  }
  thumbnails.set(key, svg);
  return svg;
}
function designStatus(text, error = false) {
  $("design-status").textContent = text;
  $("design-status").className = error ? "error" : "";
}
function showDesigns() {
  const ds = found ? found.designs : [];
  const rows = ds.map((d, k) => {
    const c = d.certificate;
    return `<tr${k === chosen ? ' class="chosen"' : ""}><td>${k + 1}</td>` +
      `<td>${k < DRAWN_DESIGNS ? thumbnail(d) : ""}</td><td>${d.largestError.toExponential(1)}</td>` +
      `<td>${c ? c.transmission.toFixed(1) + "°" : ""}</td><td>${d.start}</td>` +
      `<td><button type="button" data-design="${k}">Use</button></td></tr>`;
  });
  $("designs").innerHTML = ds.length
    ? `<tr><th>#</th><th>path</th><th>largest miss</th><th>smallest transmission</th><th>start</th><th></th></tr>${rows.join("")}` : "";
  for (const b of $("designs").querySelectorAll("button[data-design]")) {
    b.addEventListener("click", () => useDesign(Number(b.dataset.design)));
  }
  document.body.dataset.designs = String(ds.length);
}
// A design's parameters given to the page's mechanism, and everything
// redrawn: the pose, the paths, the plot.
function useDesign(k) {
  const d = found.designs[k];
  for (const [name, value] of Object.entries(d.parameters)) mechanism.setParameter(name, value);
  info = JSON.parse(mechanism.info());
  dimensionsPanel();
  chosen = k;
  resweep();
  draw(current);
  writeParameters();
  showDesigns();
  designStatus(`design ${k + 1} in use: it misses its targets by at most ${d.largestError.toExponential(1)}, ` +
    `its transmission angle at least ${d.certificate.transmission.toFixed(1)}° over the turn`);
  document.body.dataset.used = JSON.stringify(d.parameters);
}
function finished(text, error = false) {
  clearTimeout(watchdog);
  $("design-run").disabled = false;
  $("design-stop").disabled = true;
  designStatus(text, error);
  document.body.dataset.designDone = text;
}
function startWorker() {
  worker = new Worker("worker.js", { type: "module" });
  worker.onmessage = (event) => {
    const m = event.data;
    if (m.type === "error") { finished(m.message, true); return; }
    progressTimes.push(performance.now());
    found = m.found;
    $("design-progress").value = m.done / m.of;
    showDesigns();
    const none = found.designs.length === 0 && found.why ? ` (${found.why})` : "";
    const summary = `${m.done} of ${m.of} starts, ${found.designs.length} certified designs, ${(m.ms / 1000).toFixed(1)} s${none}`;
    if (m.type === "progress") designStatus(summary);
    else finished(m.type === "stopped" ? `stopped after ${summary}` : `done: ${summary}`);
  };
  worker.onerror = (e) => finished(`the search failed: ${e.message}`, true);
}
$("design-run").addEventListener("click", () => {
  if (!mechanism) return;
  const bad = readTargets().error;
  if (bad) { designStatus(bad, true); return; }
  if (!worker) startWorker();
  found = null;
  chosen = -1;
  const asked = task();
  progressTimes = [];
  searched = { text: $("editor").value, point: asked.point, targets: asked.targets };
  thumbnails.clear();
  showDesigns();
  const starts = Number($("design-starts").value);
  $("design-run").disabled = true;
  $("design-stop").disabled = false;
  designStatus("searching…");
  worker.postMessage({ type: "start", text: searched.text, task: asked, starts });
});
$("design-stop").addEventListener("click", () => {
  worker.postMessage({ type: "stop" });
  // A piece that outlasts a second: the worker ended, what it found kept.
  watchdog = setTimeout(() => {
    worker.terminate();
    worker = null;
    finished(`stopped: ${found ? found.designs.length : 0} certified designs kept`);
  }, 1000);
});
$("design-clear").addEventListener("click", () => {
  $("design-targets").value = "";
  draw(current);
});
$("design-targets").addEventListener("change", () => draw(current));
$("picture").addEventListener("click", (event) => {
  if (dragged) { dragged = false; return; }
  const svg = $("picture").querySelector("svg");
  if (!svg || !placement) return;
  const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(svg.getScreenCTM().inverse());
  const x = placement.origin[0] + p.x / placement.scale;
  const y = placement.origin[1] - (p.y - placement.top) / placement.scale;
  const text = $("design-targets").value.trim();
  $("design-targets").value = `${text ? text + "\n" : ""}${Number(x.toPrecision(6))}, ${Number(y.toPrecision(6))}`;
  draw(current);
});
$("picture").classList.add("placing");

// Exports: what is shown, as files; the editor's text in the page's link.
function save(name, type, text) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = document.createElement("a");
  a.href = url;
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
function sweepCsv() {
  const m = info.uNames.length;
  const p = info.pointNames.length;
  const head = [info.vNames[0], ...info.uNames,
    ...info.pointNames.flatMap((n) => [`${n}.x`, `${n}.y`])];
  const rows = sweep.v.map((v, i) => [v, ...sweep.u.slice(i * m, (i + 1) * m),
    ...sweep.points.slice(i * 2 * p, (i + 1) * 2 * p)].join(","));
  return [head.join(","), ...rows].join("\n") + "\n";
}
const encode = (text) => btoa(String.fromCharCode(...new TextEncoder().encode(text)));
const decode = (data) => new TextDecoder().decode(Uint8Array.from(atob(data), (c) => c.charCodeAt(0)));
function link() {
  return `${location.href.split("#")[0]}#file=${encodeURIComponent(encode($("editor").value))}`;
}
$("save-svg").addEventListener("click", () => mechanism &&
  save(`${info.name}.svg`, "image/svg+xml", mechanism.svg(640, [current, ...drive.at.slice(1)])));
$("save-dxf").addEventListener("click", () => {
  if (!mechanism) return;
  try {
    save(`${info.name}.dxf`, "application/dxf", mechanism.dxf(false));
  } catch (e) {
    status(e.message, true);
  }
});
$("save-csv").addEventListener("click", () => sweep && save(`${info.name}.csv`, "text/csv", sweepCsv()));
$("save-file").addEventListener("click", () =>
  save(`${info ? info.name : "mechanism"}.toml`, "text/plain", $("editor").value));
$("share").addEventListener("click", () => {
  history.replaceState(null, "", link());
  navigator.clipboard?.writeText(location.href).catch(() => {});
  status("the link to this mechanism is in the address bar");
});

// Another tool's mechanism, as joints and links in the editor.
function imported(make) {
  try {
    const text = make();
    $("import-status").textContent = "";
    $("editor").value = text;
    open(text);
    return true;
  } catch (e) {
    $("import-status").textContent = e.message;
    return false;
  }
}
$("import-pyslvs").addEventListener("click", () =>
  imported(() => importPyslvs($("import-text").value, $("import-inputs").value, "Imported")));
$("import-pylinkage").addEventListener("click", () =>
  imported(() => importPylinkage($("import-text").value)));

const start = files.find((x) => x.path === "four_bar.toml");
const sharedText = () => location.hash.startsWith("#file=") ? decode(decodeURIComponent(location.hash.slice(6))) : null;
const shared = sharedText();
// A link pasted into the address bar of an open page opens its mechanism.
addEventListener("hashchange", () => {
  const text = sharedText();
  if (text !== null && text !== $("editor").value) {
    $("editor").value = text;
    open(text);
  }
});
$("library").value = start.path;
$("editor").value = shared ?? start.text;
open(shared ?? start.text);
document.body.dataset.opened = info ? info.name : "";

const params = new URLSearchParams(location.search);
if (params.has("selftest")) {
  // A malformed file shows its mistakes and the page lives on.
  const broken = start.text.replace("closure = [", "closure = [ l9 +");
  const shown = showMistakes(broken) ? 0 : Number(document.body.dataset.mistakes);
  document.body.dataset.brokenMistakes = String(shown);
  document.body.dataset.brokenMessage = JSON.parse(mistakes(broken, "the editor"))[0]?.message ?? "";
  document.body.dataset.brokenMarks = JSON.stringify([...document.querySelectorAll("#editor-marks mark")].map((m) => m.textContent));
  showMistakes(start.text);
  document.body.dataset.marksAfter = String(document.querySelectorAll("#editor-marks mark").length);
  // A pyslvs four-bar imported as joints and links, and analysed.
  $("import-text").value = "M[J[R, color[Green], P[0.0, 0.0], L[ground, L1]], " +
    "J[R, color[Green], P[20.0, 0.0], L[L1, L2]], J[R, color[Green], P[70.0, 40.0], L[L2, L3]], " +
    "J[R, color[Green], P[80.0, 0.0], L[ground, L3]]]";
  const ok = imported(() => importPyslvs($("import-text").value, "[[0, 1]]", "Imported"));
  document.body.dataset.importedPyslvs = ok ? JSON.parse(mechanism.info()).uNames.join(",") : $("import-status").textContent;
  // Joints and links draw for CAD; equations say why they do not.
  document.body.dataset.dxfLayers = ok ? String((mechanism.dxf(false).match(/\nLAYER\n/g) || []).length) : "";
  const refused = imported(() => importPyslvs("M[J[nonsense", "[[0, 1]]", "Imported"));
  document.body.dataset.importRefused = refused ? "" : $("import-status").textContent;
  $("editor").value = start.text;
  open(start.text);
  try { mechanism.dxf(false); } catch (e) { document.body.dataset.dxfRefused = e.message; }
  // What the exports write, and a link that opens the same text.
  document.body.dataset.csvRows = String(sweepCsv().trim().split("\n").length);
  $("quantity").value = "transmission";
  plot();
  document.body.dataset.transmission = String(Math.min(...sweep.transmission) * 180 / Math.PI);
  $("quantity").value = "u:0";
  plot();
  document.body.dataset.link = link();
}
if (params.has("timing")) {
  // The six-bar's sweep of 720 poses and the redraw, as a drag asks them.
  const six = files.find((x) => x.path === "six_bar.toml");
  const m = Mechanism.fromText(six.text, six.path);
  const times = [];
  for (let k = 0; k < 25; k++) {
    const started = performance.now();
    const s = JSON.parse(m.sweep(720));
    const svg = m.svg(640, [s.v[k * 20]]);
    times.push(performance.now() - started);
    if (s.v.length !== 721 || !svg.startsWith("<svg")) throw new Error("the six-bar's sweep");
  }
  times.sort((a, b) => a - b);
  document.body.dataset.sixBarMs = String(times[12]);
  console.log(`six-bar: sweep of 720 poses and redraw, median of 25: ${times[12]} ms (${times[0]}–${times[24]})`);
}
// For the browser tests: the page's state, read, and its actions.
window.linkagePage = {
  get info() { return info; },
  get sweep() { return sweep; },
  get deadCentres() { return deadCentres; },
  get progressTimes() { return progressTimes; },
  get found() { return found; },
  get placement() { return placement; },
  get current() { return current; },
  setDimension,
  freeBounds,
  draw,
};
document.body.dataset.ready = "yes";
