import { checkIndex, checkFinite } from './checks.js';

/**
 * Γ(x) for x a positive integer or half-integer (x = m/2, m >= 1), computed exactly from
 * Γ(1) = 1, Γ(1/2) = √π and Γ(x + 1) = x Γ(x) — the only values the n-ball volume needs.
 *
 * @throws RangeError when `x` is not a positive multiple of 1/2.
 */
export function gammaHalfInteger(x: number): number {
  checkFinite('gammaHalfInteger', x, 'x');
  const twice = 2 * x;
  if (!Number.isInteger(twice) || twice < 1) {
    throw new RangeError(`gammaHalfInteger: argument 'x' must be a positive integer or half-integer, got ${x}`);
  }
  let value = twice % 2 === 0 ? 1 : Math.sqrt(Math.PI);
  for (let y = twice % 2 === 0 ? 1 : 0.5; y < x; y += 1) value *= y;
  return value;
}

/**
 * Volume of the n-dimensional ball of radius `radius` (m^n): V_n(ρ) = π^(n/2) ρⁿ / Γ(n/2 + 1).
 * V_0 = 1 and V_1(ρ) = 2ρ (a segment) are included because the torus formula uses V_(n−1).
 *
 * @param n - count of dimensions, an integer >= 0.
 * @param radius - radius (m), finite and >= 0.
 */
export function ballVolume(n: number, radius: number): number {
  checkIndex('ballVolume', n, 'n', 0, Number.MAX_SAFE_INTEGER);
  const rho = checkFinite('ballVolume', radius, 'radius');
  if (rho < 0) throw new RangeError(`ballVolume: argument 'radius' must be >= 0, got ${rho}`);
  return (Math.PI ** (n / 2) * rho ** n) / gammaHalfInteger(n / 2 + 1);
}
