// A diverging colour map for signed values: Moreland's cool-warm (2009) end and middle colours, blue
// (-1) through grey (0) to red (+1), interpolated linearly in sRGB.
const COOL = [59, 76, 192];
const MIDDLE = [221, 221, 221];
const WARM = [180, 4, 38];

// The colour of t in [-1, 1] (clamped) as [r, g, b] in 0..255.
export function diverging(t) {
  const s = Math.max(-1, Math.min(1, t));
  const end = s < 0 ? COOL : WARM;
  const a = Math.abs(s);
  return MIDDLE.map((m, i) => Math.round(m + (end[i] - m) * a));
}

// A CSS gradient of the map from -1 (left) to +1 (right).
export function divergingGradient(steps = 8) {
  const stops = Array.from({ length: 2 * steps + 1 }, (_, i) => {
    const t = i / steps - 1;
    return `rgb(${diverging(t).join(' ')}) ${(100 * i) / (2 * steps)}%`;
  });
  return `linear-gradient(90deg, ${stops.join(', ')})`;
}
