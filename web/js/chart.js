// Line charts on uPlot (web/vendor, loaded as a classic script: window.uPlot), themed for the dark
// page, with labelled vertical markers (Brewster, critical angle) and highlighted points.
const AXIS = { stroke: '#9aa4b1', grid: { stroke: '#262c34', width: 1 }, ticks: { stroke: '#39414c', width: 1 } };

function drawMarkers(u, markers, points) {
  const ctx = u.ctx;
  const dpr = uPlot.pxRatio;
  const { left, top, width, height } = u.bbox;
  ctx.save();
  ctx.font = `${11 * dpr}px system-ui, sans-serif`;
  markers.forEach((m, i) => {
    const x = u.valToPos(m.x, 'x', true);
    if (x < left - 1 || x > left + width + 1) return;
    ctx.strokeStyle = m.color;
    ctx.lineWidth = dpr;
    ctx.setLineDash([4 * dpr, 3 * dpr]);
    ctx.beginPath();
    ctx.moveTo(x, top);
    ctx.lineTo(x, top + height);
    ctx.stroke();
    ctx.fillStyle = m.color;
    const textWidth = ctx.measureText(m.label).width;
    const tx = x + 4 * dpr + textWidth > left + width ? x - 4 * dpr - textWidth : x + 4 * dpr;
    ctx.fillText(m.label, tx, top + (14 + 14 * i) * dpr);
  });
  ctx.setLineDash([]);
  for (const p of points) {
    ctx.strokeStyle = p.color;
    ctx.lineWidth = 1.5 * dpr;
    ctx.beginPath();
    ctx.arc(u.valToPos(p.x, 'x', true), u.valToPos(p.y, 'y', true), 4 * dpr, 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.restore();
}

// series: [{label, stroke, dash?, width?}], data: [xs, ys1, ys2, ...].
export function lineChart(container, { series, data, xLabel, xLegend, yLabel, yRange, xRange, markers = [], points = [], height = 220 }) {
  if (container.chart) container.chart.destroy();
  container.textContent = '';
  const width = () => Math.max(240, container.clientWidth);
  const opts = {
    width: width(),
    height,
    pxAlign: 0,
    scales: {
      x: { time: false, ...(xRange ? { range: xRange } : {}) },
      y: yRange ? { range: yRange } : {},
    },
    series: [
      { label: xLegend ?? xLabel, value: (u, v) => (v === null || v === undefined ? '–' : v.toFixed(1)) },
      ...series.map((s) => ({
        label: s.label,
        stroke: s.stroke,
        width: s.width ?? 1.5,
        dash: s.dash,
        points: { show: false },
        value: (u, v) => (v === null || v === undefined ? '–' : Number(v.toPrecision(4))),
      })),
    ],
    axes: [
      { ...AXIS, label: xLabel, labelSize: 18, size: 34 },
      { ...AXIS, label: yLabel, labelSize: 18, size: 52 },
    ],
    legend: { live: true },
    cursor: { drag: { x: false, y: false }, points: { size: 6 } },
    hooks: { draw: [(u) => drawMarkers(u, markers, points)] },
  };
  const plot = new uPlot(opts, data, container);
  const resize = new ResizeObserver(() => {
    if (Math.abs(plot.width - width()) > 1) plot.setSize({ width: width(), height });
  });
  resize.observe(container);
  container.chart = {
    plot,
    destroy() {
      resize.disconnect();
      plot.destroy();
    },
  };
  return container.chart;
}
