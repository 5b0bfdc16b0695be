// The report page's script and style, as text. The viewer is plain 2D canvas
// drawing (no WebGL, so it works everywhere, also headless without a GPU):
// faces sorted back to front (painter's algorithm), flat shaded, coloured by
// scaled Jacobian with the stops of the page's data.
#include "framework/report/html_figures.h"

namespace cooperage::report::detail {

const char* error_probe_script() {
  return R"JS((function () {
  var root = document.documentElement;
  function note(text) {
    root.setAttribute('data-errors', (root.getAttribute('data-errors') || '') + text + '; ');
  }
  window.addEventListener('error', function (e) { note(e.message || 'error'); });
  window.addEventListener('unhandledrejection', function (e) { note('rejected: ' + e.reason); });
  var error = console.error;
  console.error = function () {
    note(Array.prototype.join.call(arguments, ' '));
    return error.apply(console, arguments);
  };
})();)JS";
}

const char* page_style() {
  return R"CSS(
body { font: 14px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif;
       margin: 0 24px 40px; color: #222; }
h1 { font-size: 22px; margin: 18px 0 4px; }
h2 { font-size: 17px; margin: 26px 0 8px; border-bottom: 1px solid #ddd; padding-bottom: 3px; }
.summary { color: #444; margin: 0 0 6px; }
.summary b { color: #000; }
.warnings { background: #fff4e5; border: 1px solid #f0b35b; border-radius: 4px;
            padding: 4px 14px; margin-top: 12px; }
.warnings h2 { border: 0; margin: 6px 0 0; }
.pictures, .histograms { display: flex; flex-wrap: wrap; gap: 14px; }
figure { margin: 0; }
figcaption { font-size: 13px; color: #333; max-width: 520px; }
canvas.mesh { border: 1px solid #ccc; background: #f7f7f7; cursor: grab; touch-action: none; }
.hint { font-size: 12px; color: #666; }
table { border-collapse: collapse; font-size: 13px; }
th, td { border-bottom: 1px solid #e4e4e4; padding: 3px 9px; text-align: left;
         vertical-align: top; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
.bad { color: #b00020; font-weight: 600; }
.bar { background: #6a8fc4; height: 10px; min-width: 1px; }
svg text { font: 11px system-ui, sans-serif; fill: #333; }
pre { margin: 2px 0; font-size: 12px; white-space: pre-wrap; }
ol.worst { margin: 2px 0 0; padding-left: 22px; }
)CSS";
}

const char* viewer_script() {
  return R"JS((function () {
  'use strict';
  var root = document.documentElement;
  var data = JSON.parse(document.getElementById('cooperage-data').textContent);
  var stops = data.colormap.stops, inverted = data.colormap.inverted;
  var BACKGROUND = [247, 247, 247];

  function typed(b64, kind) {
    var text = atob(b64), bytes = new Uint8Array(text.length);
    for (var i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
    if (kind === 'u32') return new Uint32Array(bytes.buffer);
    if (kind === 'u16') return new Uint16Array(bytes.buffer);
    return bytes;
  }
  function colour(sj) {
    if (!(sj > 0)) return inverted;
    if (sj > 1) sj = 1;
    for (var i = 1; i < stops.length; ++i) {
      if (sj <= stops[i][0]) {
        var a = stops[i - 1], b = stops[i], t = (sj - a[0]) / (b[0] - a[0]);
        return [a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]), a[3] + t * (b[3] - a[3])];
      }
    }
    var l = stops[stops.length - 1];
    return [l[1], l[2], l[3]];
  }
  function multiply(a, b) {
    var m = new Array(9);
    for (var r = 0; r < 3; ++r)
      for (var c = 0; c < 3; ++c)
        m[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
    return m;
  }
  function rotX(t) { var c = Math.cos(t), s = Math.sin(t); return [1, 0, 0, 0, c, -s, 0, s, c]; }
  function rotY(t) { var c = Math.cos(t), s = Math.sin(t); return [c, 0, s, 0, 1, 0, -s, 0, c]; }
  function rotZ(t) { var c = Math.cos(t), s = Math.sin(t); return [c, -s, 0, s, c, 0, 0, 0, 1]; }
  // Z up, seen from the front right, a little from above.
  var INITIAL = multiply(rotX(-60 * Math.PI / 180), rotZ(-35 * Math.PI / 180));

  function Viewer(canvas, pic) {
    var n = pic.points, m = pic.faces, lo = pic.lo, hi = pic.hi;
    var q = typed(pic.pos, 'u16'), F = typed(pic.idx, pic.idxType), S = typed(pic.sj, 'u8');
    var NONE = pic.idxType === 'u16' ? 0xffff : 0xffffffff;
    var P = new Float64Array(3 * n), X = new Float64Array(3 * n);
    for (var i = 0; i < n; ++i)
      for (var c = 0; c < 3; ++c) P[3 * i + c] = lo[c] + (hi[c] - lo[c]) * q[3 * i + c] / 65535;
    var centre = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
    var radius = Math.max(1e-300, 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
    var base = new Array(m), depth = new Float64Array(m), order = new Array(m);
    for (var f = 0; f < m; ++f) base[f] = colour(S[f] / 255 * 2 - 1);
    var view = { rot: INITIAL.slice(), zoom: 1, edges: m <= 20000 };
    var ctx = canvas.getContext('2d');

    function draw() {
      var w = canvas.width, h = canvas.height, R = view.rot;
      var s = view.zoom * 0.47 * Math.min(w, h) / radius;
      ctx.fillStyle = 'rgb(' + BACKGROUND.join(',') + ')';
      ctx.fillRect(0, 0, w, h);
      for (var i = 0; i < n; ++i) {
        var dx = P[3 * i] - centre[0], dy = P[3 * i + 1] - centre[1], dz = P[3 * i + 2] - centre[2];
        X[3 * i] = w / 2 + s * (R[0] * dx + R[1] * dy + R[2] * dz);
        X[3 * i + 1] = h / 2 - s * (R[3] * dx + R[4] * dy + R[5] * dz);
        X[3 * i + 2] = s * (R[6] * dx + R[7] * dy + R[8] * dz);
      }
      for (var f = 0; f < m; ++f) {
        var k = F[4 * f + 3] === NONE ? 3 : 4, z = 0;
        for (var j = 0; j < k; ++j) z += X[3 * F[4 * f + j] + 2];
        depth[f] = z / k;
        order[f] = f;
      }
      order.sort(function (a, b) { return depth[a] - depth[b]; });
      ctx.lineWidth = view.edges ? 0.6 : 0.8;
      ctx.lineJoin = 'round';
      for (var o = 0; o < m; ++o) {
        var g = order[o], quad = F[4 * g + 3] !== NONE;
        var a = 3 * F[4 * g], b = 3 * F[4 * g + 1], c = 3 * F[4 * g + 2];
        var d = quad ? 3 * F[4 * g + 3] : c;
        // Normal in view space from the diagonals (a triangle: two edges).
        var ux = X[c] - X[a], uy = X[c + 1] - X[a + 1], uz = X[c + 2] - X[a + 2];
        var vx = quad ? X[d] - X[b] : X[b] - X[a];
        var vy = quad ? X[d + 1] - X[b + 1] : X[b + 1] - X[a + 1];
        var vz = quad ? X[d + 2] - X[b + 2] : X[b + 2] - X[a + 2];
        var nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        var len = Math.hypot(nx, ny, nz) || 1;
        var shade = 0.35 + 0.65 * Math.abs(nz) / len, rgb = base[g];
        var fill = 'rgb(' + Math.round(rgb[0] * shade) + ',' + Math.round(rgb[1] * shade) + ',' +
                   Math.round(rgb[2] * shade) + ')';
        ctx.beginPath();
        ctx.moveTo(X[a], X[a + 1]);
        ctx.lineTo(X[b], X[b + 1]);
        ctx.lineTo(X[c], X[c + 1]);
        if (quad) ctx.lineTo(X[d], X[d + 1]);
        ctx.closePath();
        ctx.fillStyle = fill;
        ctx.fill();
        ctx.strokeStyle = view.edges ? 'rgba(0,0,0,0.35)' : fill;
        ctx.stroke();
      }
      // The worst elements, on top (they may be inside the volume).
      ctx.font = 'bold 12px system-ui, sans-serif';
      for (var e = pic.worst.length - 1; e >= 0; --e) {
        var at = pic.worst[e].at;
        var px = at[0] - centre[0], py = at[1] - centre[1], pz = at[2] - centre[2];
        var sx = w / 2 + s * (R[0] * px + R[1] * py + R[2] * pz);
        var sy = h / 2 - s * (R[3] * px + R[4] * py + R[5] * pz);
        ctx.beginPath();
        ctx.arc(sx, sy, 8, 0, 2 * Math.PI);
        ctx.lineWidth = 5; ctx.strokeStyle = '#fff'; ctx.stroke();
        ctx.lineWidth = 2.5; ctx.strokeStyle = '#d0008f'; ctx.stroke();
        ctx.fillStyle = '#000';
        ctx.fillText(String(e + 1), sx + 10, sy - 8);
      }
    }

    var drag = null, pending = false;
    function redraw() {
      if (pending) return;
      pending = true;
      requestAnimationFrame(function () { pending = false; draw(); });
    }
    canvas.addEventListener('pointerdown', function (ev) {
      drag = [ev.clientX, ev.clientY];
      canvas.setPointerCapture(ev.pointerId);
    });
    canvas.addEventListener('pointermove', function (ev) {
      if (!drag) return;
      var dx = ev.clientX - drag[0], dy = ev.clientY - drag[1];
      drag = [ev.clientX, ev.clientY];
      view.rot = multiply(multiply(rotY(dx * 0.01), rotX(dy * 0.01)), view.rot);
      redraw();
    });
    canvas.addEventListener('pointerup', function () { drag = null; });
    canvas.addEventListener('wheel', function (ev) {
      ev.preventDefault();
      view.zoom *= Math.exp(-ev.deltaY * 0.0015);
      redraw();
    }, { passive: false });
    canvas.addEventListener('dblclick', function () {
      view.rot = INITIAL.slice(); view.zoom = 1; redraw();
    });
    var index = canvas.getAttribute('data-picture');
    var toggle = document.querySelector('button[data-edges="' + index + '"]');
    if (toggle) {
      toggle.addEventListener('click', function () { view.edges = !view.edges; redraw(); });
    }

    draw();
    // How much of the canvas the first picture covers (for tests and checks).
    var pixels = ctx.getImageData(0, 0, canvas.width, canvas.height).data, painted = 0;
    for (var p = 0; p < pixels.length; p += 4) {
      if (pixels[p] !== BACKGROUND[0] || pixels[p + 1] !== BACKGROUND[1] ||
          pixels[p + 2] !== BACKGROUND[2]) ++painted;
    }
    canvas.setAttribute('data-painted', String(painted));
  }

  var canvases = document.querySelectorAll('canvas.mesh');
  for (var i = 0; i < canvases.length; ++i) {
    Viewer(canvases[i], data.pictures[Number(canvases[i].getAttribute('data-picture'))]);
  }
  function rect(el) {
    if (!el) return null;
    var r = el.getBoundingClientRect();
    return [Math.round(r.left + window.scrollX), Math.round(r.top + window.scrollY),
            Math.round(r.width), Math.round(r.height)];
  }
  root.setAttribute('data-layout', JSON.stringify({
    canvas: rect(document.querySelector('canvas.mesh')),
    histogram: rect(document.querySelector('svg.histogram')),
    ratio: window.devicePixelRatio || 1
  }));
  root.setAttribute('data-ready', String(canvases.length));
})();)JS";
}

}  // namespace cooperage::report::detail
