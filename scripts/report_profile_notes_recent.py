"""The profile notes from the forty-first on. report_profile_notes.py joins
them to the earlier ones."""

PROFILE_NOTES_RECENT = """A forty-first, on the same host (commits a002884, 4c45a5e and 9a7fd7e;
callgrind, perf and scratch drivers, not committed). The time targets the
small scenes miss are set by a frame's fixed stages, not by its contacts:
in 300 fresh worlds of 30 frames of bouncing_disks (soft step 1x2) the
pairwise test of its 6 boxes ran 620 instructions a frame and the sleep
flags, read as bits of a `std::vector<bool>` in every body pass, about
270. The few-box pair test now compares x and y side by side (two-lane
SSE2 compares, the same comparisons), the sleep flags are bytes, and the
frame's finiteness check tests a body's six numbers at once. Same bits.
Instructions of those 300 worlds, whole process: bouncing_disks 58.83
-> 53.16 million (-9.6%), incline (soft step 1x8, sleeping on) 68.69 ->
66.47 (-3.2%), incline_slide -1.6%, bullet_wall (Fx2D 1x2) 34.92 ->
33.53 (-4.0%); the bench process at 1 worker: rain of 1e4 1114.3 ->
1092.2 (-2.0%), rain of 1e5 9402 -> 9196 (-2.2%), pyramid of 5050
1423.3 -> 1418.6 (-0.3%). Alternating runs of the scratch driver
(mean microseconds a frame, new over old, 7 pairs pinned to one core,
medians, while the other core was busy): bouncing_disks 0.844 (0.83 to
1.26), incline 0.956 (0.87 to 1.00), bullet_wall 0.906 (0.75 to 0.93).
The base-100 pyramid against Box2D v3 on a quiet host: the stack bench's
first second took 5.39 against 3.63 ms a frame (1.38x; the report before
this one measured 1.78x while the host was busier). Sampled with `perf`
over the bench's 2 s (both samples include the bench's own penetration
measure), our soft passes (warm start, solve and relax rows) took 36% of
our samples and Box2D v3's (its solve, warm start, and the gathering and
scattering of body states) 36% of its own: our passes, in doubles where
it uses floats, and the rest of our frame (finding and preparing the
contacts, placing the rows, publishing, the body passes) each cost about
1.4 times Box2D v3's.
"""
