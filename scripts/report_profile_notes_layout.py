"""The profile notes from the thirtieth on: where a contact point's bytes
and instructions go. report_profile_notes.py joins them to the earlier ones."""

PROFILE_NOTES_LAYOUT = """A thirtieth, on the same host as the twenty-fifth (commits 881abb4 to
d70402e; callgrind and cachegrind on scratch drivers linked to the
release build, not committed). The narrow phase's manifolds and the pair
stage's other buffers (which pairs hit, where each pair's rows and cached
contacts start, which manifolds were kept) are read until the bodies are
prepared after detection, and the soft step's rows live from packing to
publishing; since d7e6f86 and d70402e they take one block in turn
(`FrameBlock`), resident at the larger of the two sizes. Peak resident
memory above start, `collision2d_scaling_bench` on 1 worker, kB per body,
881abb4 -> d70402e: pyramid of 99681 boxes 5.28 -> 4.91, of 9870 5.39 ->
5.03, rain of 1e5 2.01 -> 1.82, of 1e4 3.73 -> 3.34; the same bits (the
golden hashes pass), the time within this host's spread. At the peak of
the pyramid of 9870 boxes (massif, d70402e) the contact points hold 43.4%
of the heap, the published contacts 24.6% and the block 9.5% (sizes
reserved, twice those in use): the two point layouts are what is left to
shrink, which is the compact per-point record of the twenty-ninth. The
instructions say the same for time. Stepping the base-20 pyramid at the
defaults from rest for 120 frames (sleeping off), ours ran 2.43 million
instructions a frame and Box2D v3 1.57 million; the warm start, solve and
relax passes 1.01 and 0.97 million, everything else 1.43 and 0.60 million
(about 1200 and 500 instructions a contact point), as the eleventh found
on the base-100 pyramid. The tiny scenes' gap to Chipmunk 7 is not the
same kind: on bullet_wall (ours Fx2D 1x2, Chipmunk 1x8) ours ran 3.16
thousand instructions a frame and Chipmunk 1.65 thousand once the bullet
had left (one world stepped on; Chipmunk mispredicted 16 branches a frame
in cachegrind's model, ours 1), and of 20000 fresh worlds of 30 frames
(allocator thresholds fixed as the sweep bench does) frames 2 to 30 took
241 and 225 ns, the first 1.53 and 0.93 us. The step's fixed stages are
what a two-body frame pays for. Two workers on the rain, this session
(scaling bench, alternating runs of 1 and 2 workers): the rain of 1e5
took 2.0 to 2.3 times less time on 2 workers in 4 pairs, the rain of 1e4
1.35 to 1.67 times in 3 pairs of 9 repetitions, against 1.6 and 1.5 in
the report at 5d4b221: the host's spells decide a single round.
"""
