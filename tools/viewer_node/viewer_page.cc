// The viewer's page: a canvas redrawn from /state.json ten times a second. The table in the
// frame of viewer_node.h; the truth as grey rings, the estimate as filled balls with their id and
// a 3-sigma ellipse, the plan's predicted path as a dashed line (a pot's other moving balls in
// yellow), each node's health beside it.
// What it drew last is also in <pre id="drawn"> as JSON (each ball's canvas pixel), so that a
// browser test can read the page's own state.
#include "tools/viewer_node/viewer_node.h"

namespace billiard::viewer {

const char* PageHtml() {
  return R"html(<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>billiard viewer</title>
<style>body{font-family:sans-serif;background:#222;color:#eee;margin:8px}
#nodes td{padding:0 8px}</style></head>
<body><canvas id="table"></canvas>
<table id="nodes"></table>
<pre id="drawn">{}</pre>
<script>
"use strict";
const canvas = document.getElementById("table");
const ctx = canvas.getContext("2d");
function draw(s) {
  const k = s.scale_px_per_m, m = s.margin_px, W = s.table.width, r = s.ball_radius * k;
  canvas.width = Math.ceil(2 * m + k * s.table.length);
  canvas.height = Math.ceil(2 * m + k * W);
  const px = (x, y) => [m + k * x, m + k * (W - y)];
  ctx.fillStyle = "#6b3a1a"; ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = "#0b7340"; ctx.fillRect(m, m, k * s.table.length, k * W);
  const drawn = {truth: [], estimate: []};
  const dashed = (path, colour) => {
    if (path.length < 2) return;
    ctx.strokeStyle = colour; ctx.setLineDash([6, 4]); ctx.beginPath();
    path.forEach((p, i) => { const [u, v] = px(p[0], p[1]);
      i ? ctx.lineTo(u, v) : ctx.moveTo(u, v); });
    ctx.stroke(); ctx.setLineDash([]);
  };
  if (s.plan) {
    dashed(s.plan.path, "#ffffff");
    // A pot's other balls, the object ball's route to its pocket among them.
    for (const b of s.plan.ball_paths || []) if (b.ball_id !== s.plan.ball_id) dashed(b.points, "#ffd23f");
  }
  if (s.truth) for (const b of s.truth.balls) {
    const [u, v] = px(b.x, b.y);
    ctx.strokeStyle = "#bbbbbb"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.arc(u, v, r + 2, 0, 2 * Math.PI); ctx.stroke();
    drawn.truth.push({id: b.id, u: u, v: v});
  }
  if (s.estimate) for (const b of s.estimate.balls) {
    const [u, v] = px(b.x, b.y);
    ctx.fillStyle = b.id === 0 ? "#ffffff" : "#ffcc00";
    ctx.beginPath(); ctx.arc(u, v, r, 0, 2 * Math.PI); ctx.fill();
    ctx.strokeStyle = "#ff4040"; ctx.lineWidth = 1;
    ctx.beginPath(); ctx.ellipse(u, v, r + 3 * k * b.sx, r + 3 * k * b.sy, 0, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.fillStyle = "#000000"; ctx.font = "11px sans-serif"; ctx.fillText(String(b.id), u - 3, v + 4);
    drawn.estimate.push({id: b.id, u: u, v: v});
  }
  const rows = Object.entries(s.nodes).map(([name, n]) =>
    `<tr><td>${name}</td><td>${n.params}</td><td>up ${n.uptime_s.toFixed(1)} s</td>` +
    `<td>received ${n.received}</td><td>dropped ${n.dropped}</td><td>${n.last_error}</td></tr>`);
  document.getElementById("nodes").innerHTML = rows.join("");
  document.getElementById("drawn").textContent = JSON.stringify(drawn);
}
async function refresh() {
  try { draw(await (await fetch("/state.json")).json()); } catch (e) { }
  setTimeout(refresh, 100);
}
refresh();
</script></body></html>
)html";
}

}  // namespace billiard::viewer
