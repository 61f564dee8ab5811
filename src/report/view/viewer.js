// The run viewer: a perspective view of DATA (see src/report/view/page.rs) drawn on a 2-D
// canvas. Positions are m in the robot's base frame (z up); forces N. The robot's points
// are computed by the generated forward kinematics when the page is written; this script
// only interpolates between frames, projects and draws.
"use strict";

(function () {
  const D = DATA;
  const T = D.t;
  const P = D.points; // points a frame: base, frame origins, tool
  const canvas = document.getElementById("scene");
  const ctx = canvas.getContext("2d");
  const info = document.getElementById("info");
  const probe = document.getElementById("probe");
  const slider = document.getElementById("time");
  const clock = document.getElementById("clock");
  const playButton = document.getElementById("play");
  const speedSelect = document.getElementById("speed");

  const t0 = T[0];
  const t1 = T[T.length - 1];

  // --- Bounds of everything drawn: the camera looks at their centre.
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  function grow(flat) {
    for (let k = 0; k + 2 < flat.length; k += 3) {
      for (let a = 0; a < 3; a++) {
        const v = flat[k + a];
        if (v !== null && isFinite(v)) {
          lo[a] = Math.min(lo[a], v);
          hi[a] = Math.max(hi[a], v);
        }
      }
    }
  }
  grow(D.xyz);
  grow(D.path);
  grow(D.ref);
  for (const s of D.surfaces) {
    for (const poly of s.fills.concat(s.lines)) grow(poly);
  }
  grow([0, 0, 0]);
  const centre = [0, 1, 2].map((a) => (lo[a] + hi[a]) / 2);
  const size = Math.max(0.2, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));

  // The force arrow: the largest force over the run is a quarter of the scene long.
  let maxForce = 0;
  for (let k = 0; k + 2 < D.force.length; k += 3) {
    const f = Math.hypot(D.force[k], D.force[k + 1], D.force[k + 2]);
    if (isFinite(f)) maxForce = Math.max(maxForce, f);
  }
  const metresPerNewton = maxForce > 0 ? (0.25 * size) / maxForce : 0;
  document.getElementById("scale").textContent = maxForce > 0
    ? "force arrow: 0.1 m = " + (0.1 / metresPerNewton).toPrecision(3) + " N"
    : "no contact force in this run";

  // --- State: the time shown, playing, the camera.
  const view = { t: t0, playing: true, speed: 1, az: -0.9, el: 0.45, dist: 2.0 * size };
  const hash = new URLSearchParams(window.location.hash.slice(1));
  if (hash.has("t")) {
    view.t = Math.min(t1, Math.max(t0, Number(hash.get("t"))));
    view.playing = false;
  }
  if (hash.has("az")) view.az = Number(hash.get("az"));
  if (hash.has("el")) view.el = Number(hash.get("el"));

  // --- The frame at time t: index i and weight w between frames i and i + 1.
  function frameAt(t) {
    let a = 0;
    let b = T.length - 1;
    if (t <= T[0]) return [0, 0];
    if (t >= T[b]) return [b, 0];
    while (b - a > 1) {
      const m = (a + b) >> 1;
      if (T[m] <= t) a = m; else b = m;
    }
    return [a, (t - T[a]) / (T[b] - T[a])];
  }
  // Point j of a flat array with `stride` numbers a frame, interpolated.
  function pointAt(flat, stride, j, i, w) {
    const k = i * stride + 3 * j;
    const n = Math.min(i + 1, T.length - 1) * stride + 3 * j;
    const out = [];
    for (let a = 0; a < 3; a++) {
      const x = flat[k + a];
      const y = flat[n + a];
      out.push(w === 0 || y === null ? x : x + w * (y - x));
    }
    return out;
  }

  // --- Camera and projection.
  let W = 0, H = 0, focal = 1, eye = [0, 0, 0], right = [1, 0, 0], up = [0, 0, 1], fwd = [0, 1, 0];
  function camera() {
    const ce = Math.cos(view.el);
    eye = [
      centre[0] + view.dist * ce * Math.cos(view.az),
      centre[1] + view.dist * ce * Math.sin(view.az),
      centre[2] + view.dist * Math.sin(view.el),
    ];
    fwd = norm(sub(centre, eye));
    right = norm(cross(fwd, [0, 0, 1]));
    up = cross(right, fwd);
    focal = 0.5 * Math.min(W, H) / Math.tan((35 * Math.PI) / 360);
  }
  function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  function norm(a) { const l = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / l, a[1] / l, a[2] / l]; }
  // Screen position of p, or null behind the camera or not a number.
  function project(p) {
    if (p[0] === null || p[1] === null || p[2] === null) return null;
    const d = sub(p, eye);
    const z = dot(d, fwd);
    if (!(z > 1e-6)) return null;
    return [W / 2 + (focal * dot(d, right)) / z, H / 2 - (focal * dot(d, up)) / z];
  }

  // --- Drawing helpers.
  function polyline(points, closed) {
    ctx.beginPath();
    let open = false;
    for (const p of points) {
      const s = project(p);
      if (s === null) { open = false; continue; }
      if (open) ctx.lineTo(s[0], s[1]); else ctx.moveTo(s[0], s[1]);
      open = true;
    }
    if (closed) ctx.closePath();
  }
  function flatPoints(flat, stride, j, upTo) {
    const out = [];
    const last = upTo === undefined ? T.length - 1 : upTo;
    for (let i = 0; i <= last; i++) {
      const k = i * stride + 3 * j;
      out.push([flat[k], flat[k + 1], flat[k + 2]]);
    }
    return out;
  }
  function triples(flat) {
    const out = [];
    for (let k = 0; k + 2 < flat.length; k += 3) out.push([flat[k], flat[k + 1], flat[k + 2]]);
    return out;
  }
  const pathPoints = flatPoints(D.path, 3, 0);
  const refPoints = flatPoints(D.ref, 3, 0);

  function draw() {
    const ratio = window.devicePixelRatio || 1;
    W = canvas.clientWidth;
    H = canvas.clientHeight;
    if (canvas.width !== Math.round(W * ratio) || canvas.height !== Math.round(H * ratio)) {
      canvas.width = Math.round(W * ratio);
      canvas.height = Math.round(H * ratio);
    }
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, W, H);
    camera();
    const [i, w] = frameAt(view.t);

    // The floor z = 0 as a grid of 0.1 m around the scene, and the base axes.
    ctx.lineWidth = 1;
    ctx.strokeStyle = "rgba(0,0,0,0.08)";
    const g0 = [Math.floor(lo[0] * 10) / 10 - 0.1, Math.floor(lo[1] * 10) / 10 - 0.1];
    const g1 = [Math.ceil(hi[0] * 10) / 10 + 0.1, Math.ceil(hi[1] * 10) / 10 + 0.1];
    for (let x = g0[0]; x <= g1[0] + 1e-9; x += 0.1) { polyline([[x, g0[1], 0], [x, g1[1], 0]]); ctx.stroke(); }
    for (let y = g0[1]; y <= g1[1] + 1e-9; y += 0.1) { polyline([[g0[0], y, 0], [g1[0], y, 0]]); ctx.stroke(); }
    const axis = 0.1 * size;
    [["#d33", [axis, 0, 0]], ["#3a3", [0, axis, 0]], ["#33d", [0, 0, axis]]].forEach(([c, e]) => {
      ctx.strokeStyle = c;
      ctx.lineWidth = 2;
      polyline([[0, 0, 0], e]);
      ctx.stroke();
    });

    // Surfaces.
    for (const s of D.surfaces) {
      ctx.fillStyle = "rgba(110,150,200,0.18)";
      for (const poly of s.fills) { polyline(triples(poly), true); ctx.fill(); }
      ctx.strokeStyle = "rgba(70,100,150,0.45)";
      ctx.lineWidth = 1;
      for (const line of s.lines) { polyline(triples(line)); ctx.stroke(); }
    }

    // Reference path, dashed; the tool's path, faint in full and solid up to now.
    ctx.setLineDash([6, 4]);
    ctx.strokeStyle = "#888";
    ctx.lineWidth = 1.5;
    polyline(refPoints);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.strokeStyle = "rgba(31,95,191,0.25)";
    polyline(pathPoints);
    ctx.stroke();
    ctx.strokeStyle = "#1f5fbf";
    ctx.lineWidth = 2;
    const tool = pointAt(D.path, 3, 0, i, w);
    polyline(pathPoints.slice(0, i + 1).concat([tool]));
    ctx.stroke();

    // The robot: links between its points, joints as dots.
    const pts = [];
    for (let j = 0; j < P; j++) pts.push(pointAt(D.xyz, 3 * P, j, i, w));
    ctx.strokeStyle = "#c0561b";
    ctx.lineWidth = 7;
    ctx.lineCap = "round";
    ctx.lineJoin = "round";
    polyline(pts);
    ctx.stroke();
    ctx.fillStyle = "#5a2a0c";
    for (const p of pts) {
      const s = project(p);
      if (s !== null) { ctx.beginPath(); ctx.arc(s[0], s[1], 4.5, 0, 2 * Math.PI); ctx.fill(); }
    }
    const drawnTool = pts[P - 1];

    // The contact force at the tool.
    const f = pointAt(D.force, 3, 0, i, w);
    const fRef = pointAt(D.force_ref, 3, 0, i, w);
    const fn = Math.hypot(f[0], f[1], f[2]);
    if (fn > 1e-6 && metresPerNewton > 0) {
      const tip = [0, 1, 2].map((a) => drawnTool[a] + f[a] * metresPerNewton);
      arrow(drawnTool, tip, "#2a9d3a");
    }

    // Text: time, force, tool, events so far.
    const past = D.events.filter((e) => e.t <= view.t + 1e-9);
    const lines = [
      D.title + " (" + D.robot + ")",
      "t = " + view.t.toFixed(3) + " s of " + t1.toFixed(3) + " s",
      "force  " + fmt(f) + " N  |F| = " + (isFinite(fn) ? fn.toFixed(1) : "-") + " N",
      "ref    " + fmt(fRef) + " N",
      "tool   " + fmt(drawnTool.map((x) => 1000 * x)) + " mm",
      "events: " + (D.events.length === 0 ? "none" : ""),
    ];
    for (const e of D.events) {
      const mark = e.t <= view.t + 1e-9 ? (e === past[past.length - 1] ? "> " : "  ") : "  ";
      const later = e.t > view.t + 1e-9 ? " (to come)" : "";
      lines.push(mark + e.t.toFixed(3) + " s  " + e.text + later);
    }
    info.textContent = lines.join("\n");
    slider.value = String(Math.round((1000 * (view.t - t0)) / Math.max(1e-9, t1 - t0)));
    clock.textContent = view.t.toFixed(3) + " s";
    probe.textContent = JSON.stringify({
      t: view.t,
      frame: i,
      frames: T.length,
      tool: drawnTool,
      errors: window.viewErrors,
    });
  }
  function fmt(v) {
    return v.map((x) => (x === null || !isFinite(x) ? "-" : x.toFixed(1)).padStart(8)).join(" ");
  }
  function arrow(from, to, colour) {
    const a = project(from);
    const b = project(to);
    if (a === null || b === null) return;
    ctx.strokeStyle = colour;
    ctx.fillStyle = colour;
    ctx.lineWidth = 3;
    ctx.beginPath();
    ctx.moveTo(a[0], a[1]);
    ctx.lineTo(b[0], b[1]);
    ctx.stroke();
    const ang = Math.atan2(b[1] - a[1], b[0] - a[0]);
    ctx.beginPath();
    ctx.moveTo(b[0], b[1]);
    ctx.lineTo(b[0] - 12 * Math.cos(ang - 0.4), b[1] - 12 * Math.sin(ang - 0.4));
    ctx.lineTo(b[0] - 12 * Math.cos(ang + 0.4), b[1] - 12 * Math.sin(ang + 0.4));
    ctx.closePath();
    ctx.fill();
  }

  // --- Controls.
  function setPlaying(on) {
    view.playing = on;
    playButton.textContent = on ? "pause" : "play";
  }
  setPlaying(view.playing);
  playButton.addEventListener("click", () => {
    if (!view.playing && view.t >= t1) view.t = t0;
    setPlaying(!view.playing);
    draw();
  });
  speedSelect.addEventListener("change", () => { view.speed = Number(speedSelect.value); });
  slider.addEventListener("input", () => {
    view.t = t0 + (Number(slider.value) / 1000) * (t1 - t0);
    setPlaying(false);
    draw();
  });
  let drag = null;
  canvas.addEventListener("pointerdown", (e) => { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener("pointerup", () => { drag = null; });
  canvas.addEventListener("pointermove", (e) => {
    if (drag === null) return;
    view.az -= 0.008 * (e.clientX - drag[0]);
    view.el = Math.max(-1.5, Math.min(1.5, view.el + 0.008 * (e.clientY - drag[1])));
    drag = [e.clientX, e.clientY];
    draw();
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    view.dist = Math.max(0.05 * size, Math.min(20 * size, view.dist * Math.exp(0.001 * e.deltaY)));
    draw();
  }, { passive: false });
  window.addEventListener("resize", draw);

  let last = null;
  function tick(now) {
    if (view.playing && last !== null) {
      view.t = Math.min(t1, view.t + ((now - last) / 1000) * view.speed);
      if (view.t >= t1) setPlaying(false);
      draw();
    }
    last = now;
    window.requestAnimationFrame(tick);
  }
  draw();
  window.requestAnimationFrame(tick);
})();
