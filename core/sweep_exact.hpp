// Internal to the sweep (core/sweep.cpp) and its distributed version (mpi/): levels at every distinct height
// (docs/theory.md section 3). A point's join time is its height's descending key; one stripe is swept in
// descending height with a record before each new height, and the records of several stripes are merged
// into the curve.
#pragma once

#include <vector>

#include "contactbench/core/stripe_components.hpp"
#include "contactbench/core/stripe_seams.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::sweep_detail {

// How many points ahead the sweeps prefetch a point's neighbours (core/sweep_exact.cpp,
// core/sweep_levels.cpp).
inline constexpr Index kPrefetchDistance = 16;

// A double's bits as an unsigned key whose ascending order is the doubles' descending order (-0.0 counts
// as +0.0, so that equal heights always have equal keys), and back.
JoinTime descending_key(Real height);
Real height_of_key(JoinTime key);

// Sweeps the points [first, last) of `heights` (row-major, the stripe's grid) in descending height (ties in
// index order) into `stripe`, with a record before every distinct height.
void sweep_stripe_exact(const HeightMap& heights, Index first, Index last, StripeComponents& stripe);

// What the merge needs of one swept stripe: its records and its final counts.
struct StripeHistory {
  std::vector<StripeRecord> records;
  Index components = 0, points = 0;
};

// The curve at every distinct height of the stripes (of n points in all), in order: at the level of time t,
// {h > z} holds the times < t, each stripe's state is the one before its first record with time >= t, and
// the spots are the stripes' components less the excess counted twice across the seams (`excess_steps`,
// core/stripe_seams.hpp). Fills z, points, spots and area_fraction of `curve`; `team` threads at most (two
// halves of the time range are merged in parallel).
void merge_exact_levels(const std::vector<StripeHistory>& stripes,
                        const std::vector<ExcessStep>& excess_steps, Index n, int team, SweepCurve& curve);

}  // namespace contactbench::sweep_detail
