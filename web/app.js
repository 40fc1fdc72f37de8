// The page: a mechanism of the library (or the text in the editor) read by
// linkage compiled to WebAssembly; its pose at the driver's value drawn by
// the library's own pictures, its numbers in a table, the file's mistakes
// listed where they are. `?selftest` records what a test reads in the DOM.
import init, { Mechanism, library, mistakes } from "./pkg/linkage_web.js";

const $ = (id) => document.getElementById(id);
let mechanism = null;
let drive = null;
let info = null;

function status(text, error = false) {
  $("status").textContent = text;
  $("status").className = error ? "error" : "";
}

function draw(value) {
  if (!mechanism) return;
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
    status(`pose and picture in ${took.toFixed(1)} ms`);
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
    draw(drive.at[0]);
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

const start = files.find((x) => x.path === "four_bar.toml");
$("library").value = start.path;
$("editor").value = start.text;
open(start.text);

const params = new URLSearchParams(location.search);
if (params.has("selftest")) {
  // A malformed file shows its mistakes and the page lives on.
  const broken = start.text.replace("closure = [", "closure = [ l9 +");
  const shown = showMistakes(broken) ? 0 : Number(document.body.dataset.mistakes);
  document.body.dataset.brokenMistakes = String(shown);
  document.body.dataset.brokenMessage = JSON.parse(mistakes(broken, "the editor"))[0]?.message ?? "";
  showMistakes(start.text);
}
document.body.dataset.ready = "yes";
