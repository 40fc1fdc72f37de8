// The page: a mechanism of the library (or the text in the editor) read by
// linkage compiled to WebAssembly; its pose at the driver's value drawn by
// the library's own pictures, its numbers in a table, the file's mistakes
// listed where they are. `?selftest` records what a test reads in the DOM.
import init, { Mechanism, importPylinkage, importPyslvs, library, mistakes } from "./pkg/linkage_web.js";

const $ = (id) => document.getElementById(id);
let mechanism = null;
let drive = null;
let info = null;
let sweep = null;
let current = 0;

function status(text, error = false) {
  $("status").textContent = text;
  $("status").className = error ? "error" : "";
}

// The plotted coordinate against the driver over the sweep, the singular
// poses met marked, the current pose as a cursor.
function plot() {
  if (!sweep || sweep.v.length < 2) { $("plot").innerHTML = ""; return; }
  // "u:k", "udot:k", "uddot:k" (coordinate k and its rates) or "transmission".
  const [series, index] = $("quantity").value.split(":");
  const k = Number(index ?? 0);
  const m = info.uNames.length;
  const xs = sweep.v;
  const ys = series === "transmission"
    ? sweep.transmission.map((a) => a * 180 / Math.PI)
    : xs.map((_, i) => sweep[series][i * m + k]);
  const label = $("quantity").selectedOptions[0].textContent;
  const [w, h, pad] = [640, 200, 40];
  const [x0, x1] = [Math.min(...xs), Math.max(...xs)];
  let [y0, y1] = [Math.min(...ys), Math.max(...ys)];
  if (y1 - y0 < 1e-12) { y0 -= 1; y1 += 1; }
  const X = (x) => pad + (w - 2 * pad) * (x - x0) / (x1 - x0 || 1);
  const Y = (y) => h - pad + (2 * pad - h) * (y - y0) / (y1 - y0);
  const path = xs.map((x, i) => `${i ? "L" : "M"}${X(x).toFixed(2)},${Y(ys[i]).toFixed(2)}`).join("");
  const marks = sweep.events.map((e) => {
    const y = series === "u" ? Y(e.u[k]) : h - pad;
    return `<circle cx="${X(e.v[0]).toFixed(2)}" cy="${y.toFixed(2)}" r="4" fill="#a00"><title>${e.kind}</title></circle>`;
  });
  const fmt = (x) => Number(x.toPrecision(4));
  $("plot").innerHTML =
    `<svg viewBox="0 0 ${w} ${h}" xmlns="http://www.w3.org/2000/svg" font-size="12" font-family="sans-serif">` +
    `<rect x="${pad}" y="${pad / 2}" width="${w - 2 * pad}" height="${h - 1.5 * pad}" fill="none" stroke="#ccc"/>` +
    `<path d="${path}" fill="none" stroke="#345" stroke-width="1.5"/>${marks.join("")}` +
    `<line id="cursor" x1="${X(current)}" x2="${X(current)}" y1="${pad / 2}" y2="${h - pad}" stroke="#07c" stroke-dasharray="4 3"/>` +
    `<text x="${pad}" y="${h - pad / 3}">${fmt(x0)}</text><text x="${w - pad}" y="${h - pad / 3}" text-anchor="end">${fmt(x1)} ${info.vNames[0]}</text>` +
    `<text x="4" y="${Y(y1) + 4}">${fmt(y1)}</text><text x="4" y="${Y(y0) + 4}">${fmt(y0)}</text>` +
    `<text x="${w / 2}" y="14" text-anchor="middle">${label} against ${info.vNames[0]}</text></svg>`;
  document.body.dataset.plotted = `${xs.length} ${sweep.events.length}`;
  $("events").innerHTML = sweep.events.map((e) =>
    `<li>${e.kind} at ${info.vNames[0]} = ${e.v[0].toPrecision(12)}</li>`).join("") +
    (sweep.complete ? "" : "<li>the sweep stops before the end of the drive range</li>");
}

function draw(value) {
  if (!mechanism) return;
  current = value;
  const v = [value];
  $("driver-value").textContent = `${info.vNames[0]} = ${v[0].toFixed(6)}`;
  try {
    const started = performance.now();
    const pose = JSON.parse(mechanism.analyze(v));
    $("picture").innerHTML = mechanism.svg(640, v);
    const took = performance.now() - started;
    const rows = info.uNames.map((n, k) =>
      `<tr><th scope="row">${n}</th><td>${pose.u[k].toPrecision(10)}</td>` +
      `<td>${pose.udot[k].toPrecision(8)}</td><td>${pose.uddot[k].toPrecision(8)}</td></tr>`);
    $("pose").innerHTML = "<tr><th></th><th>value</th><th>velocity</th><th>acceleration</th></tr>" + rows.join("");
    status(took > 0 ? `pose and picture in ${took.toFixed(1)} ms` : "pose and picture drawn");
    const cursor = document.getElementById("cursor");
    if (cursor) plot();
    document.body.dataset.pose = JSON.stringify(pose);
  } catch (e) {
    status(e.message, true);
    document.body.dataset.error = e.message;
  }
}

function showMistakes(text) {
  const found = JSON.parse(mistakes(text, "the editor"));
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
    drive = JSON.parse(mechanism.analyze([])).drive;
    const [low, high] = [Math.min(drive.from[0], drive.to[0]), Math.max(drive.from[0], drive.to[0])];
    $("driver").min = String(low);
    $("driver").max = String(high);
    $("driver").step = String((high - low) / Math.max(drive.steps, 1) / 10);
    $("driver").value = String(drive.at[0]);
    $("driver-label").textContent = info.vNames[0];
    $("quantity").innerHTML = [
      ...info.uNames.map((n, k) => `<option value="u:${k}">${n}</option>`),
      ...info.uNames.map((n, k) => `<option value="udot:${k}">${n}' (velocity)</option>`),
      ...info.uNames.map((n, k) => `<option value="uddot:${k}">${n}'' (acceleration)</option>`),
      `<option value="transmission">transmission angle (deg)</option>`,
    ].join("");
    try {
      sweep = JSON.parse(mechanism.sweep(0));
    } catch (e) {
      sweep = null;
      $("events").innerHTML = `<li>${e.message}</li>`;
    }
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
$("driver").addEventListener("input", () => draw(Number($("driver").value)));
$("quantity").addEventListener("change", plot);

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
  save(`${info.name}.svg`, "image/svg+xml", mechanism.svg(640, [current])));
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
const shared = location.hash.startsWith("#file=") ? decode(decodeURIComponent(location.hash.slice(6))) : null;
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
  showMistakes(start.text);
  // A pyslvs four-bar imported as joints and links, and analysed.
  $("import-text").value = "M[J[R, color[Green], P[0.0, 0.0], L[ground, L1]], " +
    "J[R, color[Green], P[20.0, 0.0], L[L1, L2]], J[R, color[Green], P[70.0, 40.0], L[L2, L3]], " +
    "J[R, color[Green], P[80.0, 0.0], L[ground, L3]]]";
  const ok = imported(() => importPyslvs($("import-text").value, "[[0, 1]]", "Imported"));
  document.body.dataset.importedPyslvs = ok ? JSON.parse(mechanism.info()).uNames.join(",") : $("import-status").textContent;
  const refused = imported(() => importPyslvs("M[J[nonsense", "[[0, 1]]", "Imported"));
  document.body.dataset.importRefused = refused ? "" : $("import-status").textContent;
  $("editor").value = start.text;
  open(start.text);
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
document.body.dataset.ready = "yes";
