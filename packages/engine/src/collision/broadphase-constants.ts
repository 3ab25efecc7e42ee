/** Default fattening margin of broadphase boxes (m): a tenth of a unit-sized body. */
export const DEFAULT_BROADPHASE_MARGIN = 0.1;
