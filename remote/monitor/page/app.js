// The live page: one robot's view from ringlet-monitor serve, as server-sent events (/events).
// World frame: x to the right, y up, theta from +y towards +x (hal/geometry.hpp); the robot frame
// has x ahead and y left. Everything is drawn from what the robot published; nothing is loaded
// from anywhere but the monitor.
'use strict';
const SVG = 'http://www.w3.org/2000/svg';
const $ = (id) => document.getElementById(id);
let source = null;
let chosen = new URLSearchParams(location.search).get('robot');
const diagrams = {};  // machine name -> its diagram's element
let cellsDrawn = -1;

function el(name, attrs, parent) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}
const fmt = (v, d = 2) => (typeof v === 'number' && isFinite(v) ? v.toFixed(d) : '—');
const fieldsOf = (s, type) => (s.types && s.types[type] ? s.types[type].fields : null);

// Robot frame (x ahead, y left) to the world, at pose p.
function toWorld(p, x, y) {
  const s = Math.sin(p.theta), c = Math.cos(p.theta);
  return [p.x + x * s - y * c, p.y + x * c + y * s];
}

async function loadDiagrams() {
  try {
    const paths = await (await fetch('/api/machines')).json();
    for (const path of paths) {
      const text = await (await fetch(path)).text();
      const box = document.createElement('div');
      box.className = 'diagram';
      box.innerHTML = text;
      const title = box.querySelector('svg g.graph > title');
      if (!title) continue;
      diagrams[title.textContent] = box;
      box.dataset.machine = title.textContent;
      $('diagrams').appendChild(box);
    }
  } catch (e) {
    console.warn('diagrams not loaded', e);
  }
}

function connect() {
  if (source) source.close();
  source = new EventSource('/events' + (chosen !== null ? '?robot=' + encodeURIComponent(chosen) : ''));
  source.onmessage = (e) => render(JSON.parse(e.data));
  source.onerror = () => { $('status').textContent = 'monitor unreachable: reconnecting…'; $('status').className = 'stale'; };
}

function renderPicker(s) {
  const select = $('robot');
  const ids = s.robots.map((r) => String(r.robot));
  if ([...select.options].map((o) => o.value).join() !== ids.join()) {
    select.innerHTML = '';
    for (const r of s.robots) {
      const o = document.createElement('option');
      o.value = String(r.robot);
      o.textContent = 'robot ' + r.robot;
      select.appendChild(o);
    }
  }
  if (s.robot !== null) select.value = String(s.robot);
}

function worldBounds(s, pose) {
  const plan = fieldsOf(s, 'Plan');
  if (plan && plan.map_width > 0) {
    return [plan.map_origin_x, plan.map_origin_y, plan.map_width * plan.map_resolution, plan.map_height * plan.map_resolution];
  }
  const pts = s.trajectory.slice();
  if (pose) pts.push([pose.x, pose.y]);
  if (!pts.length) return [-5, -5, 10, 10];
  const xs = pts.map((p) => p[0]), ys = pts.map((p) => p[1]);
  const x0 = Math.min(...xs) - 3, y0 = Math.min(...ys) - 3;
  return [x0, y0, Math.max(...xs) + 3 - x0, Math.max(...ys) + 3 - y0];
}

function renderWorld(s) {
  const svg = $('world');
  const poseF = fieldsOf(s, 'Pose');
  const pose = poseF && poseF.valid ? poseF : null;
  const [x0, y0, w, h] = worldBounds(s, pose);
  svg.setAttribute('viewBox', `${x0} ${-(y0 + h)} ${w} ${h}`);
  const px = Math.max(w, h) / 600;  // about one screen pixel, in metres
  let cells = svg.querySelector('#cells');
  let live = svg.querySelector('#live');
  if (!live) {
    svg.innerHTML = '';
    const flip = el('g', { transform: 'scale(1,-1)' }, svg);
    el('rect', { id: 'bounds', fill: 'none', stroke: '#ffffff55', 'stroke-width': 2 * px }, flip);
    cells = el('g', { id: 'cells', fill: '#5d4037' }, flip);
    live = el('g', { id: 'live' }, flip);
  }
  const bounds = svg.querySelector('#bounds');
  for (const [k, v] of Object.entries({ x: x0, y: y0, width: w, height: h })) bounds.setAttribute(k, v);
  const plan = fieldsOf(s, 'Plan');
  if (plan && plan.map_width > 0 && s.cells.length !== cellsDrawn) {
    cells.innerHTML = '';
    const r = plan.map_resolution;
    for (const c of s.cells) {
      const cx = c % plan.map_width, cy = Math.floor(c / plan.map_width);
      el('rect', { x: plan.map_origin_x + cx * r, y: plan.map_origin_y + cy * r, width: r, height: r }, cells);
    }
    cellsDrawn = s.cells.length;
  }
  live.innerHTML = '';
  const goals = fieldsOf(s, 'MissionGoals');
  if (goals) {
    for (let i = 0; i < goals.count; ++i) {
      el('circle', { cx: goals.x[i], cy: goals.y[i], r: Math.max(goals.tolerance, 6 * px), fill: 'none', stroke: '#ff7043', 'stroke-width': 2 * px }, live);
    }
  }
  if (plan && plan.has_plan && plan.path_count > 0) {
    const pts = [];
    for (let i = 0; i < plan.path_count; ++i) pts.push(`${plan.path_x[i]},${plan.path_y[i]}`);
    if (pose) pts.unshift(`${pose.x},${pose.y}`);
    el('polyline', { points: pts.join(' '), fill: 'none', stroke: '#ffd54f', 'stroke-width': 2.5 * px, 'stroke-dasharray': `${6 * px} ${4 * px}` }, live);
  }
  if (s.trajectory.length > 1) {
    el('polyline', { points: s.trajectory.map((p) => p.join(',')).join(' '), fill: 'none', stroke: '#90caf9', 'stroke-width': 2 * px }, live);
  }
  if (!pose) return;
  const scan = fieldsOf(s, 'LaserScan');
  if (scan) {
    // One path of short strokes (round caps: dots): one element however many beams.
    let d = '';
    for (let i = 0; i < Math.min(scan.beam_count, scan.range_mm.length); ++i) {
      if (!scan.range_mm[i]) continue;
      const b = pose.theta + scan.angle_min + i * scan.angle_increment, r = scan.range_mm[i] / 1000;
      d += `M${(pose.x + r * Math.sin(b)).toFixed(3)},${(pose.y + r * Math.cos(b)).toFixed(3)}h0`;
    }
    if (d) el('path', { d, stroke: '#ef5350', 'stroke-width': 3 * px, 'stroke-linecap': 'round' }, live);
  }
  const lines = fieldsOf(s, 'FieldLines');
  if (lines) {
    for (let i = 0; i < lines.count; ++i) {
      const [ax, ay] = toWorld(pose, lines.ground_x0[i], lines.ground_y0[i]);
      const [bx, by] = toWorld(pose, lines.ground_x1[i], lines.ground_y1[i]);
      el('line', { x1: ax, y1: ay, x2: bx, y2: by, stroke: '#e0f7fa', 'stroke-width': 3 * px }, live);
    }
    if (lines.circle_seen) {
      const [cx, cy] = toWorld(pose, lines.circle_x, lines.circle_y);
      el('circle', { cx, cy, r: lines.circle_radius, fill: 'none', stroke: '#e0f7fa', 'stroke-width': 2 * px }, live);
    }
  }
  const others = fieldsOf(s, 'RobotDetections');
  if (others) {
    for (let i = 0; i < others.count; ++i) {
      const [ox, oy] = toWorld(pose, others.foot_x[i], others.foot_y[i]);
      el('circle', { cx: ox, cy: oy, r: 6 * px, fill: '#7e57c2', stroke: '#fff', 'stroke-width': px }, live);
    }
  }
  const ball = fieldsOf(s, 'BallBelief');
  if (ball && ball.visible) {
    const [bx, by] = toWorld(pose, ball.x, ball.y);
    el('circle', { cx: bx, cy: by, r: 5 * px, fill: '#111', stroke: '#fff', 'stroke-width': 1.5 * px }, live);
  }
  // The robot: a triangle pointing along its heading.
  const size = 12 * px;
  const tip = toWorld(pose, size, 0), l = toWorld(pose, -size * 0.6, size * 0.6), r = toWorld(pose, -size * 0.6, -size * 0.6);
  el('polygon', { points: [tip, l, r].map((p) => p.join(',')).join(' '), fill: '#fff', stroke: '#111', 'stroke-width': px }, live);
}

function renderMachines(s) {
  const body = $('machines').querySelector('tbody');
  body.innerHTML = '';
  for (const m of s.machines) {
    const tr = document.createElement('tr');
    if (m.suspended) tr.className = 'suspended';
    for (const v of [m.machine, m.state, m.previous, m.ringlets, m.suspended ? 'suspended' : '']) {
      const td = document.createElement('td');
      td.textContent = v;
      tr.appendChild(td);
    }
    body.appendChild(tr);
    const box = diagrams[m.machine];
    if (!box) continue;
    box.classList.toggle('suspended', m.suspended);
    for (const node of box.querySelectorAll('g.node')) {
      const t = node.querySelector('title');
      node.classList.toggle('current', !!t && t.textContent === m.state);
    }
  }
  const list = $('transitions');
  list.innerHTML = '';
  for (const t of s.transitions.slice().reverse()) {
    const li = document.createElement('li');
    li.className = 'transition';
    li.textContent = `${t.machine}: ${t.from} → ${t.to} (ringlet ${t.ringlets}, ${fmt(t.t, 1)} s)`;
    list.appendChild(li);
  }
}

function renderTiming(s) {
  const t = fieldsOf(s, 'ExecutiveTiming');
  if (!t) return;
  $('frames').textContent = `${t.frames} frames · ${t.frame_overruns} frame overruns · ${t.slips} slips`;
  const names = t.task_names ? t.task_names.split(',') : [];
  const body = $('timing').querySelector('tbody');
  body.innerHTML = '';
  for (let i = 0; i < t.task_count; ++i) {
    const budget = t.task_budget_ns[i] / 1e6, worst = t.task_worst_ns[i] / 1e6;
    const tr = document.createElement('tr');
    // Red: the policy judged overruns; amber: the measured worst time is over the budget (in
    // lockstep budgets are judged on the modelled cost, and wall times include the simulator's).
    if (t.task_overruns[i] > 0) tr.className = 'over';
    else if (budget > 0 && worst > budget) tr.className = 'slow';
    const cells = [names[i] || `task ${i}`, t.task_every[i], fmt(budget, 3), fmt(worst, 3),
      budget > 0 ? `${fmt(100 * worst / budget, 0)} %` : '—', t.task_overruns[i], t.task_measured_overruns[i], t.task_skipped[i]];
    cells.forEach((v, k) => {
      const td = document.createElement('td');
      td.textContent = v;
      if (k > 0) td.className = 'num';
      tr.appendChild(td);
    });
    body.appendChild(tr);
  }
}

function renderStatus(s) {
  const m = fieldsOf(s, 'MissionStatus'), plan = fieldsOf(s, 'Plan');
  const parts = [];
  if (m) parts.push(`goals ${m.reached} of ${m.goal_count}${m.done ? ', done' : ''}`);
  if (plan) parts.push(`plan ${plan.status}, ${plan.replans} replans, ${plan.occupied_cells} occupied cells`);
  $('mission').textContent = parts.join(' · ') || '—';
  const h = fieldsOf(s, 'BridgeHealth');
  if (h) {
    $('health').textContent = `${h.sent} sent · ${h.missed} missed · ${h.rate_skipped} rate-limited · ${h.failed} failed · ` +
      `remote writes ${h.requests_accepted} accepted, ${h.requests_refused} refused · ${h.monitors} monitors · ${h.pumps} pumps`;
  }
}

const BUS = ['active', 'error-passive', 'bus-off'];
function renderBoard(s) {
  const b = fieldsOf(s, 'BoardHealth');
  if (!b) return;
  $('board').textContent = `${b.board_alive ? 'alive' : 'LOST'} (state ${b.board_state}) · bus ${BUS[b.bus] || b.bus} · ` +
    `${b.frames_received} frames in, ${b.frames_sent} out · ${b.malformed} malformed, ${b.unknown_id} unknown · ` +
    `${b.stale_readings} stale readings · ${b.heartbeat_losses} heartbeats lost · ${b.bus_off} bus-off · ` +
    `${b.tx_full} dropped (queue full) · ${b.board_faults} board faults` + (b.board_faults ? ` (last ${b.last_fault})` : '');
}

function render(s) {
  renderPicker(s);
  const status = $('status');
  if (s.robot === null) {
    status.textContent = 'no robot heard yet';
    status.className = 'stale';
    return;
  }
  status.textContent = `robot ${s.robot} · last heard ${fmt(s.age_s, 1)} s ago · ${s.samples} samples`;
  status.className = s.age_s > 3 ? 'stale' : '';
  const p = fieldsOf(s, 'Pose');
  if (p) {
    $('pose').textContent = p.valid
      ? `pose x ${fmt(p.x)} m · y ${fmt(p.y)} m · heading ${fmt(p.theta * 180 / Math.PI, 1)}°`
      : 'pose not valid';
  }
  renderWorld(s);
  renderMachines(s);
  renderTiming(s);
  renderStatus(s);
  renderBoard(s);
}

$('robot').addEventListener('change', (e) => {
  chosen = e.target.value;
  cellsDrawn = -1;
  $('world').innerHTML = '';
  history.replaceState(null, '', '?robot=' + encodeURIComponent(chosen));
  connect();
});
loadDiagrams().then(connect);
