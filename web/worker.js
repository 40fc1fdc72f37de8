// The page's synthesis, off the page's thread: a path synthesis on the
// engine compiled to WebAssembly, run in pieces of starts (each piece's
// designs put after those found before, so the pieces are the whole
// search) sized to take about 40 ms, its designs posted after every piece
// (a report at least every 100 ms). A stop is read between pieces; the
// page also ends the worker if a piece outlasts it.
import init, { Design } from "./pkg/linkage_web.js";

const ready = init();
let stop = false;

const PIECE_MS = 40;

onmessage = async (event) => {
  const message = event.data;
  if (message.type === "stop") {
    stop = true;
    return;
  }
  if (message.type !== "start") return;
  await ready;
  stop = false;
  let design;
  try {
    design = new Design(message.text, JSON.stringify(message.task));
  } catch (e) {
    postMessage({ type: "error", message: e.message });
    return;
  }
  const began = performance.now();
  let found = { designs: [], starts: 0, refused: 0, failedStarts: 0 };
  let piece = 1;
  while (design.done() < message.starts && !stop) {
    const count = Math.min(piece, message.starts - design.done());
    const started = performance.now();
    try {
      found = JSON.parse(design.next(count));
    } catch (e) {
      postMessage({ type: "error", message: e.message });
      return;
    }
    const perStart = (performance.now() - started) / count;
    piece = Math.max(1, Math.min(64, Math.floor(PIECE_MS / Math.max(perStart, 0.01))));
    postMessage({ type: "progress", done: design.done(), of: message.starts, found,
      ms: performance.now() - began });
    // Let a stop arrive before the next piece.
    await new Promise((resolve) => setTimeout(resolve, 0));
  }
  postMessage({ type: stop ? "stopped" : "done", done: design.done(), of: message.starts, found,
    ms: performance.now() - began });
};
