// What the prepare pass records of each pixel for the filters, in the depth channel of its guide
// (a distance is never negative, so one fetch gives both). Pixels without samples take their
// neighbours' value and give nothing. Pixels where some sample saw an emitter first are left as they
// are and lend nothing to others: an emitter is orders of magnitude brighter than what it lights, so
// the least leak would show as a halo (and dominate any squared error), and its edge is noisy by
// coverage, not by light transport.
const float kUnrendered = -1.0, kEmitter = -2.0;
