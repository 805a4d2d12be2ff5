// A Plotly chart that stays on the page across reruns: each new figure is drawn into the
// same div with Plotly.react, which changes only what changed. (st.plotly_chart names its
// element after the figure, so every change unmounted the chart and drew it from scratch.)

// plotly(src), the bundles' loader, is ui/plotly_loader.js (prepended by ui/plot.py)

// four corners, drawn as is (no ascent: Plotly flips only icons that give one)
const FULLSCREEN_ICON = {
  width: 24, height: 24,
  path: "M3 3h7v2H5v5H3zM14 3h7v7h-2V5h-5zM3 14h2v5h5v2H3zM19 19v-5h2v7h-7v-2z",
};

function toggleFullscreen(gd) {
  return document.fullscreenElement ? document.exitFullscreen() : gd.requestFullscreen();
}

// Saved under the name the page gives the chart now (a button outlives the rerun that made it)
function save(format) {
  return (gd) => gd.__Plotly.downloadImage(gd, { format, filename: gd.__filename, scale: 2 });
}

// Button objects made once per label and kept: Plotly.react compares the new config with the
// old one, functions by identity, and a config that differs makes it draw the chart from
// scratch (Plotly.newPlot) before reacting — a fresh button each rerun doubled every redraw.
const BUTTONS = new Map();

function button(name, title, icon, click) {
  const key = `${name}\n${title}`;
  if (!BUTTONS.has(key)) BUTTONS.set(key, { name, title, icon, click });
  return BUTTONS.get(key);
}

// The page's language for the toolbar's tooltips: its locale (LOCALES, written before this
// script by ui/plot.py) registered once with each bundle that draws a chart.
const REGISTERED = new WeakMap();  // Plotly → the locales it has

function locale(Plotly, name) {
  if (!LOCALES[name]) return "en";
  if (!REGISTERED.has(Plotly)) REGISTERED.set(Plotly, new Set());
  if (!REGISTERED.get(Plotly).has(name)) {
    Plotly.register(LOCALES[name]);
    REGISTERED.get(Plotly).add(name);
  }
  return name;
}

function toolbar(Plotly, labels) {
  return [button("save-svg", labels.svg, Plotly.Icons.pencil, save("svg")),
          button("save-png", labels.png, Plotly.Icons.camera, save("png")),
          button("fullscreen", labels.fullscreen, FULLSCREEN_ICON, toggleFullscreen)];
}

// Only the shapes (the builder's joints) move under the mouse; titles and legend stay put.
// One object, so that Plotly.react sees the same config every time (see BUTTONS).
const EDITABLE = { edits: { shapePosition: true } };

// A practice sheet's toolbar: zoom in, zoom out and back to the whole sheet, and no modes. In
// Plotly's pan (or zoom, or select) mode a swipe on the sheet moved the drawing (or drew a
// box) instead of scrolling the page, and the tip is moved by its own handle anyway.
const SHEET_REMOVED = ["toImage", "zoom2d", "pan2d", "select2d", "lasso2d", "autoScale2d"];
const CHART_REMOVED = ["toImage"];

// Charts waiting to be drawn, one per frame, those on screen first. Drawn one after
// another without a paint between them, the plans page's three charts (which a rerun
// brings in two or three React commits) kept its first figure off the screen until the
// last was done (bench/browser.py).
const waiting = new Map();  // chart div → its draw
let drawing = false;  // a chart was drawn and the page has not been painted since

function onScreen(gd) {
  const box = gd.getBoundingClientRect();
  return box.bottom > 0 && box.top < window.innerHeight;
}

function drawNext() {
  if (!waiting.size) {
    drawing = false;
    return;
  }
  const [gd, draw] = [...waiting].find(([div]) => onScreen(div)) || waiting.entries().next().value;
  waiting.delete(gd);
  try {
    draw();
  } finally {  // a chart that fails to draw must not stop the others
    requestAnimationFrame(() => setTimeout(drawNext));  // after the next paint
  }
}

function schedule(gd, draw) {
  waiting.set(gd, draw);  // a newer figure replaces one still waiting (or plotly.js loading)
  if (!drawing) {
    drawing = true;
    queueMicrotask(drawNext);  // after the other charts of this commit are queued too
  }
}

// The builder's drawing: its joints are Plotly shapes (circles) the user drags; the new
// centre of a dragged circle goes back to Python as the trigger "drag" ({point, x, y} in
// data units), and a click on empty paper as "click" ({x, y}), each with the size of a
// screen pixel in data units (what the mouse can aim at). A press that moves more than a
// few pixels (a drag, a pan) is not a click.
function pixel(gd) {
  return 1 / Math.abs(gd._fullLayout.xaxis._m);
}

function listen(gd, send) {
  if (gd.__listening) return;
  gd.__listening = true;
  gd.on("plotly_relayout", (change) => {
    const moved = Object.keys(change).map((k) => /^shapes\[(\d+)\]\.x0$/.exec(k)).find(Boolean);
    if (!moved) return;
    const shape = gd.layout.shapes[Number(moved[1])];
    send.current("drag", { point: shape.name, x: (shape.x0 + shape.x1) / 2,
                           y: (shape.y0 + shape.y1) / 2, pixel: pixel(gd) });
  });
  let down = null;
  gd.addEventListener("pointerdown", (e) => { down = [e.clientX, e.clientY]; }, true);
  gd.addEventListener("click", (e) => {
    const area = gd.querySelector(".nsewdrag");
    if (!down || !area || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    if (e.target !== area) return;  // on a joint, the legend or the toolbar: not paper
    const box = area.getBoundingClientRect();
    const { xaxis, yaxis } = gd._fullLayout;
    send.current("click", { x: xaxis.p2c(e.clientX - box.left), y: yaxis.p2c(e.clientY - box.top),
                            pixel: pixel(gd) });
  });
  // a double click (or double tap) on a joint: "joint" ({point}); the builder puts that
  // joint's Assur group in its other assembly. Told from two presses, not from "dblclick":
  // Plotly covers the page while a shape is pressed, so the click events miss the chart.
  let last = null;
  gd.addEventListener("pointerdown", (e) => {
    const now = { t: e.timeStamp, x: e.clientX, y: e.clientY };
    const again = last && now.t - last.t < 450 && Math.hypot(now.x - last.x, now.y - last.y) < 8;
    last = again ? null : now;
    const area = gd.querySelector(".nsewdrag");
    if (!again || !area) return;
    const box = area.getBoundingClientRect();
    const { xaxis, yaxis } = gd._fullLayout;
    const x = xaxis.p2c(e.clientX - box.left), y = yaxis.p2c(e.clientY - box.top);
    const hit = (gd.layout.shapes || []).find((s) => s.name && s.type === "circle"
      && Math.hypot(x - (s.x0 + s.x1) / 2, y - (s.y0 + s.y1) / 2) <= Math.abs(s.x1 - s.x0));
    if (hit) send.current("joint", { point: hit.name });
  }, true);
}

// Practice's sheet (spec.handle, the name of its one shape: the tip). A student moves the
// tip with a finger or the mouse, grabbed anywhere within REACH CSS px of its centre — a
// finger's 44 px, however small the tip is drawn and however far the sheet is zoomed; two
// fingers zoom the sheet about their middle (as the toolbar's + and −), so that a finger can
// place a tip to the paper's tolerance as a finer pencil would; a one-finger swipe anywhere
// else scrolls the page (the chart has no drag mode). Letting go sends "drag", as an
// editable chart does. Plotly never sees these presses: they are taken before it.
const REACH = 22;

function box(gd) {
  const area = gd.querySelector(".nsewdrag");
  return area ? area.getBoundingClientRect() : null;
}

function toData(gd, x, y) {
  const b = box(gd), { xaxis, yaxis } = gd._fullLayout;
  return [xaxis.p2c(x - b.left), yaxis.p2c(y - b.top)];
}

function toScreen(gd, x, y) {
  const b = box(gd), { xaxis, yaxis } = gd._fullLayout;
  return [b.left + xaxis.c2p(x), b.top + yaxis.c2p(y)];
}

function handle(gd, name) {
  if (gd.__handled) return;
  gd.__handled = true;
  gd.style.touchAction = "pan-x pan-y";  // the page scrolls; a pinch is the sheet's
  let grab = null, pinch = null, frame = 0;
  const index = () => (gd.layout.shapes || []).findIndex((s) => s.name === name);
  const inside = (x, y) => {
    const b = box(gd);
    return b && x >= b.left && x <= b.right && y >= b.top && y <= b.bottom;
  };
  const near = (x, y) => {  // a grab: the finger's offset from the centre, which it keeps
    const i = index();
    if (i < 0 || !box(gd)) return null;
    const s = gd.layout.shapes[i];
    const [px, py] = toScreen(gd, (s.x0 + s.x1) / 2, (s.y0 + s.y1) / 2);
    return Math.hypot(x - px, y - py) <= REACH ? { off: [px - x, py - y] } : null;
  };
  const later = (change) => {
    cancelAnimationFrame(frame);
    frame = requestAnimationFrame(() => gd.__Plotly.relayout(gd, change));
  };
  const move = (x, y) => {
    const i = index(), s = gd.layout.shapes[i];
    const [cx, cy] = toData(gd, x + grab.off[0], y + grab.off[1]);
    const rx = (s.x1 - s.x0) / 2, ry = (s.y1 - s.y0) / 2;
    grab.at = [cx, cy];
    later({ [`shapes[${i}].x0`]: cx - rx, [`shapes[${i}].x1`]: cx + rx,
            [`shapes[${i}].y0`]: cy - ry, [`shapes[${i}].y1`]: cy + ry });
  };
  const release = () => {
    if (grab && grab.at) {
      cancelAnimationFrame(frame);
      gd.__send.current("drag", { point: name, x: grab.at[0], y: grab.at[1], pixel: pixel(gd) });
    }
    grab = null;
  };
  const spread = (t) => Math.hypot(t[0].clientX - t[1].clientX, t[0].clientY - t[1].clientY);
  const zoom = (t) => {
    const k = pinch.spread / Math.max(spread(t), 1);
    const [mx, my] = pinch.middle;
    later({ "xaxis.range": pinch.x.map((v) => mx + (v - mx) * k),
            "yaxis.range": pinch.y.map((v) => my + (v - my) * k) });
  };
  const take = (e) => { e.preventDefault(); e.stopPropagation(); };
  gd.addEventListener("touchstart", (e) => {
    const t = e.touches;
    if (t.length === 2 && inside(t[0].clientX, t[0].clientY)) {
      const { xaxis, yaxis } = gd._fullLayout;
      grab = null;
      pinch = { spread: spread(t), x: [...xaxis.range], y: [...yaxis.range],
                middle: toData(gd, (t[0].clientX + t[1].clientX) / 2, (t[0].clientY + t[1].clientY) / 2) };
      take(e);
    } else if (t.length === 1 && (grab = near(t[0].clientX, t[0].clientY))) {
      take(e);
    }
  }, { capture: true, passive: false });
  gd.addEventListener("touchmove", (e) => {
    if (pinch && e.touches.length === 2) { take(e); zoom(e.touches); }
    else if (grab && e.touches.length === 1) { take(e); move(e.touches[0].clientX, e.touches[0].clientY); }
  }, { capture: true, passive: false });
  gd.addEventListener("touchend", (e) => {
    if (pinch && e.touches.length < 2) pinch = null;
    else if (grab && !e.touches.length) { take(e); release(); }
  }, { capture: true, passive: false });
  gd.addEventListener("mousedown", (e) => {
    if (e.button === 0 && (grab = near(e.clientX, e.clientY))) take(e);
  }, true);
  const moved = (e) => { if (grab && !pinch) move(e.clientX, e.clientY); };
  const up = () => { if (grab && !pinch) release(); };
  window.addEventListener("mousemove", moved);
  window.addEventListener("mouseup", up);
  gd.__unhandle = () => {
    window.removeEventListener("mousemove", moved);
    window.removeEventListener("mouseup", up);
  };
}

// A practice sheet (its layout's meta.fine: the drawing's tolerance in the sheet's units, and
// a view name) opens each step, and comes back after each drag, centred on the student's own
// tip (never on the answer) at a zoom where the tolerance is FINE_PX screen pixels or more: a
// phone drawing the whole sheet gave it 0.83 px, less than a finger can aim at. A sheet
// already that fine is left whole; zoom out (or reset) to see it all, and the next drag
// brings the fine view back around the tip.
const FINE_PX = 3;

// A new step opens on a window that holds its tail and its answer's region (want.centre and
// want.reach, cm: on a grid and rounded up, figures/practice.py): at the fine zoom where it
// fits, else zoomed out just enough to hold it (a phone: the answer in view, not off it).
function fine(gd, spec) {
  const want = (gd.layout.meta || {}).fine;
  if (!want || gd.__fine === want.view) return;
  gd.__fine = want.view;
  const size = gd._fullLayout._size;
  const tip = (gd.layout.shapes || []).find((s) => s.name === spec.handle);
  if (!tip || !size) return;
  const room = want.reach || 0;
  let perPixel = want.tolerance / FINE_PX;
  perPixel = Math.max(perPixel, (2 * room) / Math.min(size.w, size.h));
  if (pixel(gd) <= perPixel) return;  // drawn that fine already: left whole
  const [x, y] = want.centre || [(tip.x0 + tip.x1) / 2, (tip.y0 + tip.y1) / 2];
  const half = [size.w * perPixel / 2, size.h * perPixel / 2];
  gd.__Plotly.relayout(gd, { "xaxis.range": [x - half[0], x + half[0]],
                             "yaxis.range": [y - half[1], y + half[1]] });
}

// What a page asks to have on the screen once this chart is drawn (spec.focus: "selector|n"),
// once for each n: practice's step prompt after a check or a move.
function focus(gd, spec) {
  if (!spec.focus || spec.focus === gd.__focused) return;
  gd.__focused = spec.focus;
  const target = document.querySelector(spec.focus.split("|")[0]);
  if (!target) return;
  const header = document.querySelector("[data-testid='stHeader']");  // fixed over the page
  target.style.scrollMarginTop = `${(header ? header.offsetHeight : 0) + 8}px`;
  target.scrollIntoView({ block: "start" });
}

// φ₂ in the browser (ui/crank.py): a slider and play controls under the chart. The first
// touch asks the server for the figure's frames over a turn (the trigger "frames"); from
// then on every chart of the same group redraws locally while φ₂ moves, and only letting
// go (or pausing, or a step button) goes back to the server, as the trigger "at". The same
// control moves a link's length (spec.key "L3", in metres), with a list of the lengths it
// can move (spec.choices): picking one asks for that one's frames.
function frameFigure(gd, k) {
  const turn = gd.__crank.spec.turn;
  const patch = turn && turn.frames[k];
  if (!patch) return null;  // no frames yet, or the mechanism cannot be drawn there
  return patched(gd, turn.base, patch);
}

// a frame (ui/crank.py's patch) laid over the figure ``base`` and the layout the chart showed
function patched(gd, base, patch) {
  const moved = patch.data || {};
  const data = patch.all  // every trace: a number is the base's trace of that index
    ? patch.all.map((tr) => (typeof tr === "number" ? base.data[tr] : tr))
    : base.data.map((tr, i) => (moved[i] ? { ...tr, ...moved[i] } : tr));
  return { data, layout: fitted(gd, patch.layout ? { ...gd.__layout, ...patch.layout } : gd.__layout) };
}

// the control's slider and words at frame k (✕ where the mechanism cannot be drawn)
function showIndex(crank, k) {
  const { spec } = crank;
  crank.index = k;
  crank.range.value = String(k);
  const reachable = !spec.turn || spec.turn.frames[k];
  const value = String(spec.values[k]).replace(".", crank.decimal);
  crank.label.textContent = `${spec.label} = ${value}${spec.unit}${reachable ? "" : " ✕"}`;
  crank.label.title = reachable ? "" : crank.unreachable;  // why the chart does not move
  // a screen reader names the slider and reads the value, not the frame's index
  crank.range.setAttribute("aria-label", `${spec.label} [${spec.unit.trim()}]`);
  crank.range.setAttribute("aria-valuetext", crank.label.textContent);
}

function showFrame(gd, k) {
  showIndex(gd.__crank, k);
  const fig = frameFigure(gd, k);
  if (fig && gd.__Plotly) {
    schedule(gd, () => gd.__Plotly.react(gd, { ...fig, config: gd.__config })
      .then(() => keepLabelsInside(gd)));
  }
}

function moveCrank(gd, k, release) {
  const { spec } = gd.__crank;
  window.dispatchEvent(new CustomEvent("mehanizmi-crank", { detail: { group: spec.group, index: k } }));
  const url = new URL(window.location.href);  // the link follows φ₂ while it moves
  url.searchParams.set(spec.key, String(spec.values[k]));
  window.history.replaceState(window.history.state, "", url);
  if (release) gd.__send.current("at", spec.values[k]);
}

function askFrames(gd, choice) {
  const crank = gd.__crank;
  if (choice === undefined && (crank.spec.turn || crank.asked)) return;
  crank.asked = true;
  gd.__send.current("frames", choice === undefined ? true : choice);
}

// the list of what the control moves (spec.choices: [key, name] each), kept up to date
function showChoices(crank) {
  const { choices, key } = crank.spec;
  crank.choice.hidden = choices.length < 2;
  crank.choice.replaceChildren(...choices.map(([value, name]) => new Option(name, value)));
  crank.choice.value = key;
}

function crankButton(text, title, click) {
  const b = document.createElement("button");
  b.type = "button";
  b.textContent = text;
  b.title = title;
  b.setAttribute("aria-label", title);  // the symbols ◀ ▶ ❚❚ say nothing to a screen reader
  b.addEventListener("click", click);
  return b;
}

function crankControls(gd, labels) {
  const crank = gd.__crank;
  if (crank.box) return;
  const box = document.createElement("div");
  box.className = "mehanizmi-crank";
  box.style.cssText = "display:flex;flex-wrap:wrap;align-items:center;gap:0.5em;padding:0.3em 0;"
    + "font-size:0.9em";  // on a phone the slider and its value take a row of their own
  const range = document.createElement("input");
  range.type = "range";
  range.min = "0";
  range.step = "1";
  range.style.flex = "1 1 10em";
  const label = document.createElement("span");
  label.style.minWidth = "6.5em";
  const n = () => crank.spec.values.length;
  let timer = null;
  const play = crankButton("▶", labels.play, () => {
    if (crank.stop()) {
      moveCrank(gd, crank.index, true);
      return;
    }
    if (!crank.spec.turn) {  // play once the frames are here
      crank.playing = true;
      askFrames(gd);
      return;
    }
    crank.start();
  });
  crank.start = () => {
    crank.playing = false;
    play.textContent = "❚❚";
    play.title = labels.pause;
    play.setAttribute("aria-label", labels.pause);
    timer = setInterval(() => moveCrank(gd, ahead(), false), 80);
  };
  crank.stop = () => {
    if (timer === null) return false;
    clearInterval(timer);
    timer = null;
    play.textContent = "▶";
    play.title = labels.play;
    play.setAttribute("aria-label", labels.play);
    return true;
  };
  // played, a turn goes round; a length goes back and forth between its slider's ends
  let heading = 1;
  const ahead = () => {
    if (crank.spec.wraps) return (crank.index + 1) % n();
    if (crank.index + heading < 0 || crank.index + heading > n() - 1) heading = -heading;
    return crank.index + heading;
  };
  // a step goes round a turn; a length stops at its slider's ends
  const next = (by) => (crank.spec.wraps ? (crank.index + by + n()) % n()
    : Math.min(Math.max(crank.index + by, 0), n() - 1));
  const step = (by) => () => {
    crank.stop();
    askFrames(gd);
    moveCrank(gd, next(by), true);
  };
  range.addEventListener("pointerdown", () => askFrames(gd));
  range.addEventListener("input", () => { crank.stop(); moveCrank(gd, Number(range.value), false); });
  range.addEventListener("change", () => moveCrank(gd, Number(range.value), true));
  const choice = document.createElement("select");
  choice.setAttribute("aria-label", labels.choice);
  choice.addEventListener("change", () => { crank.stop(); askFrames(gd, choice.value); });
  const back = crankButton("◀", "", step(-1)), forward = crankButton("▶|", "", step(1));
  box.append(choice, back, play, forward, range, label);
  gd.after(box);
  Object.assign(crank, { box, range, label, choice, back, forward });
  crank.follow = (e) => {
    if (e.detail.group === crank.spec.group) showFrame(gd, e.detail.index);
  };
  window.addEventListener("mehanizmi-crank", crank.follow);
}

function updateCrank(gd, spec) {
  if (!spec.crank) {
    dropCrank(gd);
    return;
  }
  const crank = gd.__crank = gd.__crank || {};
  const same = crank.spec && crank.spec.key === spec.crank.key;
  crank.spec = spec.crank;
  crank.unreachable = spec.labels.unreachable;
  crank.decimal = spec.separators ? spec.separators[0] : ".";
  crank.asked = false;
  crankControls(gd, spec.labels);
  crank.range.max = String(spec.crank.values.length - 1);
  for (const [button, sign] of [[crank.back, "−"], [crank.forward, "+"]]) {
    const title = `${spec.crank.label} ${sign}${spec.crank.step.replace(".", crank.decimal)}`;
    button.title = title;
    button.setAttribute("aria-label", title);
  }
  showChoices(crank);
  // the server's value, unless the student is on the control (moving the same quantity)
  const onIt = same && crank.box.contains(document.activeElement) && spec.crank.turn;
  showIndex(crank, onIt ? crank.index : spec.crank.index);
  if (crank.playing && spec.crank.turn) crank.start();
}

function dropCrank(gd) {
  const crank = gd.__crank;
  if (!crank) return;
  if (crank.stop) crank.stop();
  if (crank.follow) window.removeEventListener("mehanizmi-crank", crank.follow);
  if (crank.box) crank.box.remove();
  gd.__crank = null;
}

// A page's own slider that a chart follows (spec.crank.follows: the slider's key, which
// Streamlit writes as the class "st-key-<key>" on its box). While the keyboard is on it, each
// run sends the chart's figures one step of the slider either side of its value
// (spec.crank.near: patches on the figure shown); an arrow key draws the one it moves to at
// once, and the rerun's own figure replaces that drawing when it comes (issue 83: the rerun
// alone painted the first figure 1.6–2.2 times later than the floor's slider). The browser
// tells the server when the keyboard comes onto such a slider and when it leaves them all
// (the trigger "near"), so that no other run pays for the neighbours. A touch screen's
// finger focuses a slider with no keyboard to follow: there the first arrow key tells it.
let keyboardOn = null;  // the followed slider the server was last told of
const TOUCH = window.matchMedia("(pointer: coarse)").matches;

function sliderKey(el) {
  const slider = el && el.closest ? el.closest("[data-testid='stSlider']") : null;
  const box = slider && slider.closest("[class*='st-key-']");
  const name = box && [...box.classList].find((c) => c.startsWith("st-key-"));
  return name ? name.slice("st-key-".length) : null;
}

function followers(key) {
  return [...document.querySelectorAll(".mehanizmi-plot")]
    .filter((gd) => gd.__crank && gd.__crank.spec.follows.includes(key));
}

function tellKeyboard(key) {
  const chart = followers(key || keyboardOn)[0];
  if (!chart || keyboardOn === key) return;
  keyboardOn = key;
  chart.__send.current("near", key);
}

window.addEventListener("focusin", (e) => {
  const key = sliderKey(e.target);
  if (!TOUCH && key !== null && followers(key).length) tellKeyboard(key);
});
window.addEventListener("focusout", (e) => {
  const next = sliderKey(e.relatedTarget);
  // a window left (another tab) keeps the slider: its focus comes back with the window
  const onAnother = next !== null && followers(next).length > 0;
  if (keyboardOn !== null && document.hasFocus() && !onAnother) tellKeyboard(null);
});
window.addEventListener("keydown", (e) => {
  const by = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 }[e.key];
  const key = sliderKey(e.target);
  if (!by || key === null || e.target.type !== "range" || e.shiftKey || e.altKey || e.ctrlKey
      || e.metaKey) return;  // (shift moves a page of steps)
  const charts = followers(key);
  if (!charts.length) return;
  tellKeyboard(key);  // (told already by its focus, but on a touch screen)
  const step = Number(e.target.step);
  const value = Number(e.target.value) + by * step;  // the slider reads its old value still
  for (const gd of charts) {
    const near = gd.__crank.spec.near;
    const k = near && near.key === key && gd.__figure
      ? near.values.findIndex((v) => Math.abs(v - value) < step / 1000) : -1;
    const patch = k < 0 ? null : near.frames[k];
    if (!patch) continue;  // (the server's figure comes as without a preview)
    gd.__previewed = true;
    const fig = patched(gd, gd.__figure, patch);
    schedule(gd, () => gd.__Plotly.react(gd, { ...fig, config: gd.__config })
      .then(() => keepLabelsInside(gd)));
  }
}, true);  // before the slider's own handler, which stops the key's propagation

// A figure's margins are fixed (figures/style.margins), sized for the page's main column; on
// a phone a chart is half as wide. Each figure and frame is drawn with:
// - its title in as many lines as the chart's width needs (Plotly draws a title on one line,
//   and a scene's name ran off the chart's right edge), the top margin grown by the lines;
// - on a phone, its title under the toolbar: a touch screen shows Plotly's toolbar at all
//   times, across most of a narrow chart's top, and it lay over the title (the builder's
//   drawing keeps its own compact top, see below);
// - the room its legend took when drawn (fitLegend).
const MEASURE = document.createElement("canvas").getContext("2d");

const TOOLBAR = 36;  // px: the height of Plotly's toolbar row, and some air under it

// A phone's screen, as ui/frame.css's narrow layout: a touch screen there shows Plotly's
// toolbar at all times (a desktop's shows it under the mouse only, whatever a chart's width).
function onPhone() {
  return window.innerWidth <= 640;
}

function fitted(gd, layout) {
  const title = layout.title || {};
  const size = (title.font || {}).size || 18;
  const line = Math.ceil(1.3 * size);
  const lines = titleLines(title.text || "", size, (layout.font || {}).family, gd.clientWidth);
  const text = lines.join("<br>");
  const margin = { ...layout.margin };
  if (gd.__legendRoom > margin.b) margin.b = gd.__legendRoom;
  if (lines.length > 1) margin.t = (margin.t ?? 100) + (lines.length - 1) * line;
  const under = title.text && onPhone() && !gd.__editable;
  if (!under && lines.length < 2 && margin.b === (layout.margin || {}).b) return layout;
  // (Plotly lifts a title of n lines by n − 1 of them, as it grows the margin above)
  const lifted = (text.split("<br>").length - 1) * line;
  const placed = under ? { yref: "container", y: 1, yanchor: "top", pad: { t: TOOLBAR + lifted } } : {};
  if (under) margin.t = (margin.t ?? 100) + TOOLBAR;
  return { ...layout, margin, title: { ...title, ...placed, text } };
}

function titleLines(text, size, family, width) {
  if (!width || text.includes("<br>")) return [text];
  MEASURE.font = `bold ${size}px ${family || "sans-serif"}`;
  const wide = (words) => MEASURE.measureText(words.replace(/<[^>]+>/g, "")).width > width - 10;
  const lines = [""];
  for (const word of text.split(" ")) {
    const line = lines[lines.length - 1];
    if (line && wide(`${line} ${word}`)) lines.push(word);
    else lines[lines.length - 1] = line ? `${line} ${word}` : word;
  }
  return lines;
}

// A horizontal legend under a chart wraps into as many rows as the chart's width needs. On a
// phone it wraps into more rows than the margin has room for and covered the x axis's labels
// and title: the margin grows to the legend's measured height (one more draw), and the
// chart keeps that room for the figures and frames it draws next.
function fitLegend(gd) {
  const { legend, font, margin, showlegend } = gd._fullLayout;
  if (!showlegend || !legend || legend.orientation !== "h" || !legend._height) return null;
  const room = Math.ceil(2 * font.size + 30 + legend._height);  // the axis's labels and title
  if (room <= margin.b + font.size) return null;  // as on the desktop: the title only nears it
  gd.__legendRoom = room;
  return gd.__Plotly.relayout(gd, { "margin.b": room });
}

// A label beside a point is written to its right ("top right": a force's value at its
// arrow's middle). On a phone's narrow chart one near the plot's right edge ran past it and
// was cut ("F₅ = 10" for 100 N): such a label moves left until it ends at the edge. Checked
// after every draw, as Plotly places the labels anew; on a desktop no label reaches the edge.
function keepLabelsInside(gd) {
  const size = gd._fullLayout && gd._fullLayout._size;
  if (!size) return;
  const right = gd.getBoundingClientRect().left + size.l + size.w;
  // every label measured before any is moved: a move between two measurements made the
  // browser lay the page out again for the next (a scrub's step paid one layout a label)
  const texts = [...gd.querySelectorAll(".textpoint text")];
  const overs = texts.map((text) => text.getBoundingClientRect().right - right);
  texts.forEach((text, i) => {
    if (overs[i] > 1) text.setAttribute("x", String(Number(text.getAttribute("x")) - overs[i] - 2));
  });
}

// A page's first run in a session leaves out what can wait until its first chart is on the
// screen (ui/firstpaint.py); the first chart drawn says so once, after the frame that paints
// it, and the rerun that starts brings the rest. (A chart of that first run keeps gd.__first
// until the rerun's figure replaces it: the browser tests wait for that.)
function reportFirstPaint(gd) {
  if (window.__mehanizmiPainted) return;
  window.__mehanizmiPainted = true;
  requestAnimationFrame(() => setTimeout(() => gd.__send.current("painted", true)));
}

export default function (component) {
  const { data, parentElement, setTriggerValue } = component;
  let gd = parentElement.querySelector(".mehanizmi-plot");
  if (!gd) {
    gd = document.createElement("div");
    gd.className = "mehanizmi-plot";
    gd.style.background = "white";
    parentElement.appendChild(gd);
  }
  const text = new TextDecoder().decode(data);
  if (gd.__drawn === text) return;
  gd.__drawn = text;
  // each mount's draws are its own: a chart taken off the page (a fragment's tick can
  // unmount and mount it again) is purged while Plotly may still be drawing it, and that
  // draw then fails inside Plotly ("e.emit is not a function": purge removed the div's
  // event methods). Such a failure is not this mount's and is not shown.
  const generation = (gd.__generation = (gd.__generation || 0) + 1);
  const failed = (error) => {
    if (gd.__generation !== generation) return;
    gd.__drawn = gd.__figureText = null;  // the same figure sent again draws again
    gd.textContent = String(error);
  };
  const spec = JSON.parse(text);
  // the same figure with only the chart's own control changed (its frames or neighbours
  // came) is not drawn again, unless a neighbour was drawn over it (a preview, above)
  const figureText = JSON.stringify({ ...spec, crank: null });
  const same = gd.__figureText === figureText && !gd.__previewed;
  gd.__figureText = figureText;
  gd.__previewed = false;
  gd.__first = spec.first;
  if (!spec.first) window.__mehanizmiPainted = false;  // a whole run: the next first run reports
  gd.__filename = spec.filename;
  gd.__editable = Boolean(spec.editable);  // (fitted: the builder's drawing keeps its own top)
  gd.__send = gd.__send || { current: null };
  gd.__send.current = setTriggerValue;  // the newest mount's, as Streamlit hands it over
  updateCrank(gd, spec);
  if (!same) draw(gd, spec, failed);
  // called when the chart leaves the page: free Plotly's listeners. Streamlit also calls it
  // for a chart that stays (a fragment's tick on a page whose join panel sits above the
  // live part): purged then, mid-draw, the chart showed "TypeError: e.emit is not a
  // function" and stayed blank until new data came. So only a chart whose div really left
  // the document is purged.
  return () => setTimeout(() => {
    if (gd.isConnected) return;
    gd.__generation += 1;  // a draw still under way is no longer this chart's
    gd.__drawn = gd.__figureText = null;  // mounted again with the same figure, it is drawn again
    waiting.delete(gd);
    dropCrank(gd);
    if (gd.__unhandle) gd.__unhandle();
    if (gd.__Plotly) gd.__Plotly.purge(gd);
  });
}

function draw(gd, spec, failed) {
  plotly(spec.src).then((Plotly) => schedule(gd, () => {
    // one toolbar button per file format instead of Plotly's camera (one format, set in
    // advance); no "Share chart" to Plotly's cloud (plotly.js 4 shows it by default): a
    // page's own link shares it, and the app needs no network
    const config = { responsive: true, displaylogo: false, showSendToCloud: false,
                     modeBarButtonsToRemove: spec.handle ? SHEET_REMOVED : CHART_REMOVED,
                     modeBarButtonsToAdd: toolbar(Plotly, spec.labels),
                     locale: locale(Plotly, spec.locale),
                     ...(spec.editable ? EDITABLE : {}) };
    gd.__config = config;  // the frames of φ₂ are drawn with the same config (see BUTTONS)
    // the page's decimal mark on ticks and hover labels (Serbian: 0,25), frames included
    if (spec.separators) spec.figure.layout = { ...spec.figure.layout, separators: spec.separators };
    gd.__layout = spec.figure.layout;  // and over the same layout
    gd.__figure = spec.figure;  // (a slider's neighbours are patches on it)
    if (gd.__Plotly && gd.__Plotly !== Plotly) gd.__Plotly.purge(gd);  // drawn by another bundle
    gd.__Plotly = Plotly;
    let layout = fitted(gd, spec.figure.layout);
    if (spec.handle) {  // a sheet as tall as the screen's width allows, not the page's 600 px
      layout = { ...layout, height: Math.min(layout.height || 600, Math.max(320, gd.clientWidth + 100)) };
    } else if (spec.editable && onPhone()) {  // the builder's drawing, held at
      // the top of a phone's screen over the tables (ui/layout.py): half of it, given to
      // the drawing (the legend and the title's size are the room a phone lacks)
      const title = layout.title || {};
      layout = { ...layout, height: Math.min(layout.height || 600, Math.round(0.5 * window.innerHeight)),
                 showlegend: false, margin: { ...layout.margin, t: 36, b: 44 },
                 title: { ...title, font: { ...(title.font || {}), size: 13 } } };
    }
    Plotly.react(gd, { ...spec.figure, layout, config })
      .then(() => fitLegend(gd))
      .then(() => keepLabelsInside(gd))
      .then(() => {
        if (spec.editable) listen(gd, gd.__send);
        if (spec.handle) handle(gd, spec.handle);
        fine(gd, spec);
        focus(gd, spec);
        if (spec.first && gd.__first) reportFirstPaint(gd);  // (not if a whole run's figure came since)
      })
      .catch(failed);
  })).catch(failed);
}
