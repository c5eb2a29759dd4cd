// The six face neighbours of the Poisson stencil, in the order every solver kernel visits them
// (-x, +x, -y, +y, -z, +z: pairs per axis, for pair_total's mirror-exact sums). Its own file so
// kernels that do not bind the fine level's cell types (the multigrid restriction) share it.
const ivec3 kPoissonNeighbours[6] = ivec3[6](ivec3(-1, 0, 0), ivec3(1, 0, 0), ivec3(0, -1, 0),
                                             ivec3(0, 1, 0), ivec3(0, 0, -1), ivec3(0, 0, 1));
