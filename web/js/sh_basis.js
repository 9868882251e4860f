// The real spherical harmonics of the API (GET /envmaps/{id}/sh states its convention): orthonormal,
// without the Condon-Shortley phase, z up, theta from +z, phi from +x toward +y, ordered by l, then m
// from -l to l; so band 1 is sqrt(3 / (4 pi)) (y, z, x).

// (l - m)! / (l + m)!
function factorialRatio(l, m) {
  let r = 1;
  for (let k = l - m + 1; k <= l + m; ++k) r /= k;
  return r;
}

// P_l^m(x) for every l < bands and 0 <= m <= l, without the Condon-Shortley phase: p[l][m].
function legendre(bands, x) {
  const s = Math.sqrt(Math.max(0, 1 - x * x));
  const p = Array.from({ length: bands }, () => new Float64Array(bands));
  let pmm = 1;
  for (let m = 0; m < bands; ++m) {
    if (m > 0) pmm *= (2 * m - 1) * s;
    p[m][m] = pmm;
    if (m + 1 < bands) p[m + 1][m] = x * (2 * m + 1) * pmm;
    for (let l = m + 2; l < bands; ++l) p[l][m] = (x * (2 * l - 1) * p[l - 1][m] - (l + m - 1) * p[l - 2][m]) / (l - m);
  }
  return p;
}

// Normalisation factors K_lm of every l < bands, 0 <= m <= l (times sqrt 2 for m > 0): k[l][m].
function shNormalisation(bands) {
  return Array.from({ length: bands }, (_, l) => Float64Array.from({ length: l + 1 }, (__, m) =>
    Math.sqrt(((2 * l + 1) / (4 * Math.PI)) * factorialRatio(l, m)) * (m > 0 ? Math.SQRT2 : 1)));
}

// The terms of Y_lm that depend on theta alone (K_lm P_l^|m|(cos theta)) and on phi alone (sqrt 2
// cos(m phi), sqrt 2 sin(|m| phi) or 1, the sqrt 2 in K), in the API's order.
function polarTerms(bands, theta, k) {
  const p = legendre(bands, Math.cos(theta));
  const out = new Float64Array(bands * bands);
  for (let l = 0; l < bands; ++l) for (let m = -l; m <= l; ++m) out[l * l + l + m] = k[l][Math.abs(m)] * p[l][Math.abs(m)];
  return out;
}

function azimuthTerms(bands, phi) {
  const out = new Float64Array(bands * bands);
  for (let l = 0; l < bands; ++l)
    for (let m = -l; m <= l; ++m) out[l * l + l + m] = m > 0 ? Math.cos(m * phi) : m < 0 ? Math.sin(-m * phi) : 1;
  return out;
}

// Y_lm(theta, phi) for the bands^2 functions, in the API's order.
export function shBasis(bands, theta, phi) {
  const [a, b] = [polarTerms(bands, theta, shNormalisation(bands)), azimuthTerms(bands, phi)];
  return a.map((x, i) => x * b[i]);
}

// The reconstruction sum c_lm Y_lm of one channel's coefficients at the pixel centres of a lat-long
// image of width x height (row 0 at the top: theta = pi (y + 0.5) / height, phi = 2 pi (x + 0.5) /
// width): a Float32Array of width * height.
export function shReconstruct(coefficients, width, height) {
  const bands = Math.round(Math.sqrt(coefficients.length));
  const k = shNormalisation(bands);
  const columns = Array.from({ length: width }, (_, x) => azimuthTerms(bands, (2 * Math.PI * (x + 0.5)) / width));
  const out = new Float32Array(width * height);
  for (let y = 0; y < height; ++y) {
    const row = polarTerms(bands, (Math.PI * (y + 0.5)) / height, k).map((v, i) => v * coefficients[i]);
    for (let x = 0; x < width; ++x) {
      let sum = 0;
      for (let i = 0; i < row.length; ++i) sum += row[i] * columns[x][i];
      out[y * width + x] = sum;
    }
  }
  return out;
}
