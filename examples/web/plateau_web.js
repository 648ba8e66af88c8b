// plateau_web.js - the page of examples/web/index.html: boundaries, the
// solve through the WebAssembly module (plateau_wasm.c), a canvas 2-D
// picture.  No library, nothing fetched: the module comes as base64 from
// plateau_wasm_base64.js (PLATEAU_WASM_BASE64), written by `make web`.
//
// The module imports nothing (WebAssembly.Module.imports is empty; the page
// shows it under "imports"); it exports its memory and the pw_* functions.
//
// Address parameters (used by tests/web_check.sh): shape, n, method (0 1 2),
// twist (degrees), height, yaw and pitch (the view, degrees; without them
// the page turns the view to the film's front side), points=x,y,z;x,y,z;... (a custom boundary, read
// with Number(), correctly rounded like strtod), repeat=K (solve K times and
// show the fastest and the median time), drag=I,DX,DY (after the first
// solve, drag boundary vertex I by DX, DY pixels: the check of dragging).
"use strict";

(function () {
  const $ = (id) => document.getElementById(id);
  const params = new URLSearchParams(window.location.search);

  // ---- boundaries ------------------------------------------------------
  // Each shape: the sliders' meaning and defaults, and its polygon.
  const SHAPES = {
    helicoid: {
      twist: ["how far the strip turns (degrees)", 90], height: ["rise per radian of turn", 1.9],
      // r(u, v) = (u cos v, u sin v, b v), u in [-1, 1], v in [-T/2, T/2]:
      // the sides of the parameter rectangle, 7 vertices each (as
      // cli/samples/helicoid.txt at the defaults)
      points: (twist, b) => rectangle(7, -1, 1, -twist / 2, twist / 2,
        (u, v) => [u * Math.cos(v), u * Math.sin(v), b * v]),
    },
    catenoid: {
      twist: ["width of the arc (degrees)", 90], height: ["height of the patch", 1.0],
      // r(u, v) = (b cos u cosh v, b v, b sin u cosh v), b = 2.05,
      // u in [pi/2 - T/2, pi/2 + T/2], v in [-h/2, h/2], 6 per side
      points: (twist, h) => rectangle(6, Math.PI / 2 - twist / 2, Math.PI / 2 + twist / 2,
        -h / 2, h / 2,
        (u, v) => [2.05 * Math.cos(u) * Math.cosh(v), 2.05 * v, 2.05 * Math.sin(u) * Math.cosh(v)]),
    },
    saddle: {
      twist: ["rotation of the saddle (degrees)", 0], height: ["height of its waves", 0.4],
      // (cos t, sin t, h cos 2(t - turn)), 24 vertices
      points: (twist, h) => ring(24, (t) => [Math.cos(t), Math.sin(t), h * Math.cos(2 * (t - twist / 2))]),
    },
    ring: {
      twist: ["twist (degrees)", 60], height: ["height of its waves", 0.5],
      // a three-wave ring whose vertices turn about z with their height:
      // (cos(t + a), sin(t + a), h sin 3t), a = (twist / 2) sin 3t; 36 vertices
      points: (twist, h) => ring(36, (t) => {
        const a = 0.5 * twist * Math.sin(3 * t);
        return [Math.cos(t + a), Math.sin(t + a), h * Math.sin(3 * t)];
      }),
    },
  };

  function rectangle(k, u0, u1, v0, v1, f) {
    // k vertices per side (each side's first corner), counter-clockwise in (u, v)
    const pts = [];
    const steps = k;
    for (let i = 0; i < steps; i++) pts.push(f(u0 + (u1 - u0) * i / steps, v0));
    for (let i = 0; i < steps; i++) pts.push(f(u1, v0 + (v1 - v0) * i / steps));
    for (let i = 0; i < steps; i++) pts.push(f(u1 - (u1 - u0) * i / steps, v1));
    for (let i = 0; i < steps; i++) pts.push(f(u0, v1 - (v1 - v0) * i / steps));
    return pts;
  }

  function ring(m, f) {
    const pts = [];
    for (let i = 0; i < m; i++) pts.push(f(2 * Math.PI * i / m));
    return pts;
  }

  // ---- the module --------------------------------------------------------
  let wasm = null; // instance exports
  let wasmBytes = 0;

  function decodeBase64(text) {
    const bin = atob(text);
    const out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out;
  }

  function cString(ptr) {
    const mem = new Uint8Array(wasm.memory.buffer);
    let end = ptr;
    while (mem[end] !== 0) end++;
    return new TextDecoder().decode(mem.subarray(ptr, end));
  }

  // ---- state ---------------------------------------------------------------
  let boundary = []; // [[x, y, z], ...]
  let mesh = null;   // {pos: Float64Array, tri: Int32Array}
  let view = { yaw: -0.6, pitch: 0.5, scale: 1, center: [0, 0, 0] };
  let solveQueued = false;

  function readControls() {
    return {
      shape: $("shape").value,
      twist: Number($("twist").value) * Math.PI / 180,
      height: Number($("height").value),
      n: Number($("n").value),
      method: Number($("method").value),
    };
  }

  function showControls() {
    const c = readControls();
    $("twist-value").textContent = $("twist").value;
    $("height-value").textContent = Number($("height").value).toFixed(2);
    $("n-value").textContent = c.n;
    const s = SHAPES[c.shape];
    $("twist").disabled = $("height").disabled = !s;
    if (s) {
      $("twist-label").textContent = s.twist[0];
      $("height-label").textContent = s.height[0];
    }
  }

  function setShapeDefaults() {
    const s = SHAPES[$("shape").value];
    if (!s) return;
    $("twist").value = s.twist[1];
    $("height").value = s.height[1];
  }

  function rebuildBoundary() {
    const c = readControls();
    const s = SHAPES[c.shape];
    if (s) boundary = s.points(c.twist, c.height);
    fitView();
  }

  // Which side of the film the eye sees from (yaw, pitch).  A triangle
  // shows its front when it turns counter-clockwise on the screen: its
  // normal by the right-hand rule points at the eye (draw() paints it
  // blue).  The library orients the mesh with the polygon, so the sum of
  // the triangles' normals is the polygon's vector area, whatever the
  // mesh: its component towards the eye, over its length (in [-1, 1];
  // positive: mostly front), is known before anything is solved.
  function facing(yaw, pitch) {
    const keep = [view.yaw, view.pitch];
    view.yaw = yaw;
    view.pitch = pitch;
    const p = boundary.map(project);
    view.yaw = keep[0];
    view.pitch = keep[1];
    let nx = 0, ny = 0, nz = 0;
    for (let i = 1; i + 1 < p.length; i++) {
      const ux = p[i][2] - p[0][2], uy = p[i][3] - p[0][3], uz = p[i][4] - p[0][4];
      const vx = p[i + 1][2] - p[0][2], vy = p[i + 1][3] - p[0][3], vz = p[i + 1][4] - p[0][4];
      nx += uy * vz - uz * vy;
      ny += uz * vx - ux * vz;
      nz += ux * vy - uy * vx;
    }
    const len = Math.hypot(nx, ny, nz);
    return len > 0 ? nz / len : 0;
  }

  // Open on the film's front side: keep the default oblique view when it
  // shows the front, else the nearest turn (in steps of 30 degrees, from
  // above first, then from below) that does; a film seen edge-on from
  // every one of them keeps the one that shows most of its front.
  function faceFront() {
    const yaw0 = -0.6, pitch0 = 0.5;
    let best = [yaw0, pitch0], bestF = facing(yaw0, pitch0);
    for (const pitch of [pitch0, -pitch0]) {
      for (let k = 0; k <= 6; k++) {
        for (const sign of k === 0 || k === 6 ? [1] : [1, -1]) {
          const yaw = yaw0 + sign * k * Math.PI / 6, f = facing(yaw, pitch);
          if (f >= 0.3) {
            view.yaw = yaw;
            view.pitch = pitch;
            return;
          }
          if (f > bestF) { best = [yaw, pitch]; bestF = f; }
        }
      }
    }
    view.yaw = best[0];
    view.pitch = best[1];
  }

  function fitView() {
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (const p of boundary) for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], p[k]); hi[k] = Math.max(hi[k], p[k]);
    }
    view.center = [0, 1, 2].map((k) => 0.5 * (lo[k] + hi[k]));
    const r = 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
    const cv = $("view");
    view.scale = 0.45 * Math.min(cv.width, cv.height) / r;
  }

  function boundaryText() {
    // String(x) is the shortest text that reads back as the same double
    return boundary.map((p) => p.map(String).join(" ")).join("\n") + "\n";
  }

  // ---- solving -------------------------------------------------------------
  function solveOnce(c) {
    const m = boundary.length;
    const ptr = wasm.pw_boundary(m);
    if (!ptr) return { r: -1, ms: 0 };
    const b = new Float64Array(wasm.memory.buffer, ptr, 3 * m);
    boundary.forEach((p, i) => { b[3 * i] = p[0]; b[3 * i + 1] = p[1]; b[3 * i + 2] = p[2]; });
    const t0 = performance.now();
    const r = wasm.pw_solve(m, c.n, c.method);
    return { r: r, ms: performance.now() - t0 };
  }

  function solve() {
    solveQueued = false;
    if (!wasm) return;
    const c = readControls();
    const repeat = Math.max(1, Math.min(50, Number(params.get("repeat")) || 1));
    const times = [];
    let res = null;
    for (let k = 0; k < repeat; k++) {
      res = solveOnce(c);
      times.push(res.ms);
    }
    times.sort((a, b) => a - b);
    const ms = times[(times.length - 1) >> 1];
    const bt = $("boundary-text");
    bt.textContent = boundaryText(); // the DOM text too: a dump shows it
    // 1 when the lines do not wrap (white-space pre, as wrap="off" sets it)
    // and every one shows whole, without scrolling sideways (the dumped DOM
    // carries it: tests/web_check.sh reads it)
    const ws = getComputedStyle(bt).whiteSpace;
    document.body.setAttribute("data-boundary-fits",
      (ws === "pre" || ws === "nowrap") && bt.scrollWidth <= bt.clientWidth ? "1" : "0");
    const st = $("status");
    if (res.r !== 0) {
      st.textContent = (res.r < 0 ? "bad boundary size" :
        cString(wasm.pw_result_name(res.r)) + ": " + cString(wasm.pw_message()));
      st.className = "num bad";
      ["area", "F", "iterations", "rounds", "size", "angles"].forEach((id) => { $(id).textContent = ""; });
      mesh = null;
    } else {
      const defects = wasm.pw_defects();
      st.textContent = defects === 0 ? "valid" : cString(wasm.pw_defects_string());
      st.className = defects === 0 ? "num" : "num bad";
      // String(x): every digit needed to read the double back exactly
      $("area").textContent = String(wasm.pw_area());
      $("F").textContent = wasm.pw_f().toExponential(3);
      $("iterations").textContent = String(wasm.pw_iterations());
      $("rounds").textContent = String(wasm.pw_rounds());
      const nv = wasm.pw_num_vertices(), nt = wasm.pw_num_triangles();
      $("size").textContent = nv + " / " + nt;
      $("angles").textContent = wasm.pw_min_angle().toFixed(1) + " .. " + wasm.pw_max_angle().toFixed(1);
      mesh = {
        pos: new Float64Array(wasm.memory.buffer, wasm.pw_positions(), 3 * nv).slice(),
        tri: new Int32Array(wasm.memory.buffer, wasm.pw_triangles(), 3 * nt).slice(),
      };
    }
    $("time").textContent = repeat > 1
      ? "min " + times[0].toFixed(1) + " ms, median " + ms.toFixed(1) + " ms of " + repeat
      : ms.toFixed(1) + " ms";
    $("heap").textContent = (wasm.pw_heap_peak() / 1048576).toFixed(2) + " MiB";
    const solves = Number(document.body.getAttribute("data-solved") || 0) + 1;
    document.body.setAttribute("data-solved", String(solves));
    draw();
    if (solves === 1 && params.has("drag")) scriptedDrag(params.get("drag"));
  }

  // drag=I,DX,DY: after the first solve, drag boundary vertex I by DX, DY
  // pixels through the same pointer handlers a mouse uses
  function scriptedDrag(spec) {
    const [i, dx, dy] = spec.split(",").map(Number);
    if (!(i >= 0 && i < boundary.length)) return;
    const p = project(boundary[i]);
    const r = $("view").getBoundingClientRect();
    const at = (x, y) => ({ clientX: r.left + x, clientY: r.top + y, pointerId: 1 });
    onDown(at(p[0], p[1]));
    onMove(at(p[0] + dx, p[1] + dy));
    onUp();
  }

  function queueSolve() {
    // one solve for any number of changes queued before it runs (a timer,
    // not requestAnimationFrame, which headless checks never see fire)
    if (solveQueued) return;
    solveQueued = true;
    setTimeout(solve, 0);
  }

  // ---- drawing -------------------------------------------------------------
  function project(p) {
    // turn about z by yaw, then tilt about the screen's x axis by pitch
    const x = p[0] - view.center[0], y = p[1] - view.center[1], z = p[2] - view.center[2];
    const cy = Math.cos(view.yaw), sy = Math.sin(view.yaw);
    const cp = Math.cos(view.pitch), sp = Math.sin(view.pitch);
    const x1 = cy * x - sy * y, y1 = sy * x + cy * y;
    const up = cp * z - sp * y1, depth = sp * z + cp * y1;
    const cv = $("view");
    // screen x, screen y, then the view coordinates: right, up, away from the eye
    return [cv.width / 2 + view.scale * x1, cv.height / 2 - view.scale * up, x1, up, depth];
  }

  function unprojectDelta(dx, dy) {
    // a screen displacement as a 3-D one in the screen plane
    const cy = Math.cos(view.yaw), sy = Math.sin(view.yaw);
    const cp = Math.cos(view.pitch), sp = Math.sin(view.pitch);
    const a = dx / view.scale, u = -dy / view.scale;
    // screen x axis: (cy, -sy, 0); screen up: (sp sy, sp cy, cp) up to sign
    return [a * cy + u * (-sp * sy), a * -sy + u * (-sp * cy), u * cp];
  }

  function draw() {
    const cv = $("view");
    const g = cv.getContext("2d");
    g.clearRect(0, 0, cv.width, cv.height);
    if (mesh) {
      const nv = mesh.pos.length / 3, nt = mesh.tri.length / 3;
      const scr = new Array(nv);
      for (let i = 0; i < nv; i++) scr[i] = project([mesh.pos[3 * i], mesh.pos[3 * i + 1], mesh.pos[3 * i + 2]]);
      const order = [];
      for (let t = 0; t < nt; t++) {
        const a = mesh.tri[3 * t], b = mesh.tri[3 * t + 1], c = mesh.tri[3 * t + 2];
        order.push([scr[a][4] + scr[b][4] + scr[c][4], t]);
      }
      order.sort((p, q) => q[0] - p[0]); // far first
      let frontArea = 0, allArea = 0;
      g.lineWidth = 0.6;
      g.strokeStyle = "rgba(30, 40, 60, 0.55)";
      for (const [, t] of order) {
        const a = scr[mesh.tri[3 * t]], b = scr[mesh.tri[3 * t + 1]], c = scr[mesh.tri[3 * t + 2]];
        // the facet normal in view coordinates: which side faces the eye,
        // and a two-sided shade against a light over the eye's left shoulder
        const ux = b[2] - a[2], uy = b[3] - a[3], uz = b[4] - a[4];
        const vx = c[2] - a[2], vy = c[3] - a[3], vz = c[4] - a[4];
        const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const len = Math.hypot(nx, ny, nz) || 1;
        const shade = 0.3 + 0.7 * Math.abs((-0.35 * nx + 0.45 * ny - 0.82 * nz) / len);
        // counter-clockwise on the screen: the normal points at the eye
        const front = nz > 0;
        allArea += Math.abs(nz);
        if (front) frontArea += Math.abs(nz);
        const base = front ? [90, 140, 210] : [220, 160, 90];
        g.fillStyle = "rgb(" + base.map((v) => Math.round(v * shade)).join(",") + ")";
        g.beginPath();
        g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]); g.lineTo(c[0], c[1]);
        g.closePath();
        g.fill();
        g.stroke();
      }
      // the share of the picture's area that shows the front (the dumped
      // DOM carries it: tests/web_check.sh reads it)
      document.body.setAttribute("data-front-share", (allArea > 0 ? frontArea / allArea : 0).toFixed(3));
    }
    // the boundary polygon and its vertices
    const bs = boundary.map(project);
    g.lineWidth = 2;
    g.strokeStyle = "#c0392b";
    g.beginPath();
    bs.forEach((p, i) => (i ? g.lineTo(p[0], p[1]) : g.moveTo(p[0], p[1])));
    g.closePath();
    g.stroke();
    g.fillStyle = "#c0392b";
    bs.forEach((p, i) => {
      g.beginPath();
      g.arc(p[0], p[1], i === dragVertex ? 6 : 3.5, 0, 2 * Math.PI);
      g.fill();
    });
    g.fillStyle = "#555";
    g.font = "12px system-ui, sans-serif";
    g.fillText("blue: the film's front side, orange: its back; drag a red vertex to move it", 10, cv.height - 10);
  }

  // ---- interaction ---------------------------------------------------------
  let dragVertex = -1, dragStart = null;

  function pointer(ev) {
    const r = $("view").getBoundingClientRect();
    return [ev.clientX - r.left, ev.clientY - r.top];
  }

  function onDown(ev) {
    const [x, y] = pointer(ev);
    let best = -1, bestD = 12;
    boundary.map(project).forEach((p, i) => {
      const d = Math.hypot(p[0] - x, p[1] - y);
      if (d < bestD) { bestD = d; best = i; }
    });
    dragVertex = best;
    dragStart = [x, y];
    try {
      $("view").setPointerCapture(ev.pointerId);
    } catch (e) {
      // a synthetic pointer (the drag= parameter) cannot be captured
    }
  }

  function onMove(ev) {
    if (!dragStart) return;
    const [x, y] = pointer(ev);
    const dx = x - dragStart[0], dy = y - dragStart[1];
    dragStart = [x, y];
    if (dragVertex >= 0) {
      const d = unprojectDelta(dx, dy);
      const p = boundary[dragVertex];
      boundary[dragVertex] = [p[0] + d[0], p[1] + d[1], p[2] + d[2]];
      queueSolve();
    } else {
      view.yaw += dx * 0.01;
      view.pitch = Math.max(-1.55, Math.min(1.55, view.pitch + dy * 0.01));
      draw();
    }
  }

  function onUp() {
    dragStart = null;
    dragVertex = -1;
    draw();
  }

  // ---- start -----------------------------------------------------------------
  function applyParams() {
    const pts = params.get("points");
    if (pts) {
      boundary = pts.split(";").filter((s) => s.trim()).map((s) => s.split(",").map(Number));
      $("shape").value = "custom";
    } else if (SHAPES[params.get("shape")]) {
      $("shape").value = params.get("shape");
    }
    setShapeDefaults();
    if (params.has("twist")) $("twist").value = params.get("twist");
    if (params.has("height")) $("height").value = params.get("height");
    if (params.has("n")) {
      $("n").max = Math.max(400, Number(params.get("n")));
      $("n").value = params.get("n");
    }
    if (params.has("method")) $("method").value = params.get("method");
    if (pts) fitView();
    else rebuildBoundary();
    if (params.has("yaw") || params.has("pitch")) {
      if (params.has("yaw")) view.yaw = Number(params.get("yaw")) * Math.PI / 180;
      if (params.has("pitch")) view.pitch = Number(params.get("pitch")) * Math.PI / 180;
    } else {
      faceFront();
    }
  }

  async function start() {
    applyParams();
    showControls();
    $("shape").addEventListener("change", () => {
      setShapeDefaults(); showControls(); rebuildBoundary(); faceFront(); queueSolve();
    });
    for (const id of ["twist", "height"]) {
      $(id).addEventListener("input", () => { showControls(); rebuildBoundary(); queueSolve(); });
    }
    for (const id of ["n", "method"]) {
      $(id).addEventListener("input", () => { showControls(); queueSolve(); });
    }
    const cv = $("view");
    cv.addEventListener("pointerdown", onDown);
    cv.addEventListener("pointermove", onMove);
    cv.addEventListener("pointerup", onUp);
    cv.addEventListener("pointercancel", onUp);
    try {
      const bytes = decodeBase64(window.PLATEAU_WASM_BASE64);
      wasmBytes = bytes.length;
      const result = await WebAssembly.instantiate(bytes, {});
      wasm = result.instance.exports;
      const imports = WebAssembly.Module.imports(result.module);
      $("wasm-bytes").textContent = String(wasmBytes);
      $("imports").textContent = imports.length ? imports.map((i) => i.module + "." + i.name).join(" ") : "none";
    } catch (e) {
      $("status").textContent = "could not load the module: " + e;
      $("status").className = "num bad";
      return;
    }
    solve();
  }

  start();
})();
