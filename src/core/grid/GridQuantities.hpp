// GridQuantities: what the density grid accumulates per node, in this order, in every
// flat per-node array (step accumulator, window slots, window sum, restart state):
// node n holds values[n * nQuantities + q]. All are sums over parcels of the parcel's
// node weight w_g (eq. 24) times the parcel's total:
#pragma once

namespace dropletFiber
{

enum GridQuantity : int
{
    quantityMass = 0,        // sum w n m(r_p)                     (eq. 25), kg
    quantityCount = 1,       // sum w n                             droplets
    quantityCountRadius = 2, // sum w n r_p                         number-mean radius numerator (eq. 10)
    quantityMassRadius = 3,  // sum w n m(r_p) r_p                  mass-mean radius numerator
    quantityMomentumX = 4,   // sum w n m(r_p) u                    mass-mean velocity numerator
    quantityMomentumY = 5,
    quantityMomentumZ = 6,
    nQuantities = 7
};

} // namespace dropletFiber
