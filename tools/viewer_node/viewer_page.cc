// The viewer's page: a canvas redrawn from /state.json ten times a second, first from the state
// the page was served with. The table (wood, cloth, cushion lines, pockets) in the frame of
// viewer_node.h; the last shot's paths in each ball's colour (a stripe's dashed); the planned
// stroke's predicted paths dotted; the truth as grey rings; the estimate as balls in their
// colours with their numbers and a 3-sigma ellipse; one status line (the stroke, its
// probability, the nodes' health) under it, cut to the page's width.
// What it drew last is also in <script type="application/json" id="drawn"> (each ball's number
// and canvas pixel, each pocket's), so that a browser test reads the page's own record.
#include <string>

#include "tools/viewer_node/viewer_node.h"

namespace billiard::viewer {

namespace {

constexpr char kPageHead[] = R"html(<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>billiard viewer</title>
<style>body{font-family:sans-serif;background:#222;color:#eee;margin:8px}
#status{white-space:nowrap;overflow:hidden;text-overflow:ellipsis;max-width:1096px;
font-size:14px;margin-top:4px}#status .error{color:#ff8080}</style></head>
<body><canvas id="table"></canvas>
<div id="status">waiting for the loop</div>
<script type="application/json" id="drawn">{}</script>
<script>
"use strict";
const initial = )html";

constexpr char kPageTail[] = R"html(;
const canvas = document.getElementById("table");
const ctx = canvas.getContext("2d");
function line(points, px, colour, width, dash) {
  if (points.length < 2) return;
  ctx.strokeStyle = colour; ctx.lineWidth = width; ctx.setLineDash(dash); ctx.beginPath();
  points.forEach((p, i) => { const [u, v] = px(p[0], p[1]); i ? ctx.lineTo(u, v) : ctx.moveTo(u, v); });
  ctx.stroke(); ctx.setLineDash([]);
}
function drawTable(s, px, drawn) {
  const t = s.table, k = s.scale_px_per_m;
  ctx.fillStyle = "#6b3a1a"; ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = "#0b7340"; ctx.beginPath();
  t.outline.forEach((p, i) => { const [u, v] = px(p[0], p[1]); i ? ctx.lineTo(u, v) : ctx.moveTo(u, v); });
  ctx.closePath(); ctx.fill();
  for (const c of t.cushions) line(c, px, "#054d29", 2, []);
  for (const p of t.pockets) {
    const [u, v] = px(p.centre[0], p.centre[1]);
    ctx.fillStyle = "#000000"; ctx.beginPath(); ctx.arc(u, v, k * p.radius, 0, 2 * Math.PI); ctx.fill();
    drawn.pockets.push({name: p.name, u: u, v: v});
  }
}
// A ball as a player knows it: its colour, a stripe's band across white, its label on a white
// spot (pool's number; "?" on a ball not told yet; none on the cue ball and snooker's).
function drawBall(b, u, v, r) {
  ctx.save(); ctx.beginPath(); ctx.arc(u, v, r, 0, 2 * Math.PI); ctx.clip();
  ctx.fillStyle = b.look.body; ctx.fillRect(u - r, v - r, 2 * r, 2 * r);
  if (b.look.band) { ctx.fillStyle = b.look.band; ctx.fillRect(u - r, v - 0.55 * r, 2 * r, 1.1 * r); }
  ctx.restore();
  ctx.strokeStyle = "#000000"; ctx.lineWidth = 0.7;
  ctx.beginPath(); ctx.arc(u, v, r, 0, 2 * Math.PI); ctx.stroke();
  if (!b.label) return;
  ctx.fillStyle = "#ffffff"; ctx.beginPath(); ctx.arc(u, v, 0.5 * r, 0, 2 * Math.PI); ctx.fill();
  ctx.fillStyle = "#000000"; ctx.font = "bold 9px sans-serif";
  ctx.textAlign = "center"; ctx.textBaseline = "middle";
  ctx.fillText(b.label, u, v + 0.5);
}
function drawBalls(s, px, drawn) {
  const k = s.scale_px_per_m, r = s.ball_radius * k;
  if (s.truth) for (const b of s.truth.balls) {
    const [u, v] = px(b.x, b.y);
    ctx.strokeStyle = "#bbbbbb"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.arc(u, v, r + 2, 0, 2 * Math.PI); ctx.stroke();
    drawn.truth.push({id: b.id, number: b.number, u: u, v: v});
  }
  // The balls from the estimate; from the truth where no estimator is heard.
  const shown = s.estimate ? s.estimate.balls : s.truth ? s.truth.balls : [];
  for (const b of shown) {
    const [u, v] = px(b.x, b.y);
    drawBall(b, u, v, r);
    if (s.estimate) {
      ctx.strokeStyle = "#ff4040"; ctx.lineWidth = 1; ctx.beginPath();
      ctx.ellipse(u, v, r + 3 * k * b.sx, r + 3 * k * b.sy, 0, 0, 2 * Math.PI); ctx.stroke();
      drawn.estimate.push({id: b.id, number: b.number, u: u, v: v});
    }
  }
}
function strokeText(p) {
  if (p.status !== 0) return `<span class="error">planner: ${escape(p.reason)}</span>`;
  const pot = p.object_ball === null ? "safe stroke" : `${escape(p.object_name)} in ${p.pocket.replace("_", " ")}`;
  const chance = p.probability === null ? "" :
    `, pot chance ${(100 * p.probability).toFixed(0)} ± ${(100 * p.probability_stderr).toFixed(0)} %`;
  return `${pot}: ${p.cue_speed_m_s.toFixed(2)} m/s at ${p.heading_deg.toFixed(1)}°, tip ` +
    `${p.tip_side_mm.toFixed(1)} mm right, ${p.tip_height_mm.toFixed(1)} mm up${chance}`;
}
function escape(text) {
  return String(text).replace(/[&<>"]/g, c => ({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;"})[c]);
}
function statusText(s) {
  const parts = [`${s.strokes} strokes planned`];
  if (s.plan) parts.push(strokeText(s.plan));
  for (const [name, n] of Object.entries(s.nodes)) {
    parts.push(n.last_error ? `<span class="error">${escape(name)}: ${escape(n.last_error)}</span>`
                            : `${escape(name)} up ${n.uptime_s.toFixed(0)} s`);
  }
  return parts.join(" · ");
}
function draw(s) {
  const k = s.scale_px_per_m, m = s.margin_px, W = s.table.width;
  canvas.width = Math.ceil(2 * m + k * s.table.length);
  canvas.height = Math.ceil(2 * m + k * W);
  const px = (x, y) => [m + k * x, m + k * (W - y)];
  const drawn = {pockets: [], truth: [], estimate: [], paths: []};
  drawTable(s, px, drawn);
  for (const p of s.paths) {
    line(p.points, px, p.look.path, 2, p.look.dashed ? [8, 5] : []);
    drawn.paths.push({number: p.number, points: p.points.length});
  }
  if (s.plan) {
    line(s.plan.path, px, "#ffffff", 1, [2, 4]);
    for (const b of s.plan.ball_paths) if (b.number !== 0) line(b.points, px, b.look.path, 1, [2, 4]);
  }
  drawBalls(s, px, drawn);
  document.getElementById("status").innerHTML = statusText(s);
  document.getElementById("drawn").textContent = JSON.stringify(drawn);
}
draw(initial);
async function refresh() {
  try { draw(await (await fetch("/state.json")).json()); } catch (e) { }
  setTimeout(refresh, 100);
}
setTimeout(refresh, 100);
</script></body></html>
)html";

}  // namespace

std::string PageHtml(const nlohmann::json& state) {
  // The state inside a <script>: "</" written "<\/" (the same string to JavaScript), so that no
  // text from a message (a node's error, a planner's reason) can close the script.
  std::string json = state.dump();
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 3)) {
    json.replace(at, 2, "<\\/");
  }
  return kPageHead + json + kPageTail;
}

}  // namespace billiard::viewer
