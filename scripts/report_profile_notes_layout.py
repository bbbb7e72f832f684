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

A thirty-first, on the same host (commit 89f8a55, and scratch drivers
linked to the release build, not committed). Where the growing rain's
memory went: at frame 110 of the rain of 1e4, glibc's heap held 10.1 MB
of freed blocks, still resident, and `malloc_trim` gave back 7.8 MB of
them (resident 39.8 -> 32.0 MB). They were the blocks the contact points
and the published contacts had outgrown, each half the size of the next
and seldom reused whole. Since 89f8a55 a freed block of 256 KiB or more
first gives its whole pages back to the system (`give_back_pages`,
`madvise` with `MADV_DONTNEED`): the frame buffers, the frame block, and
the published contacts once their new block is taken. Peak resident
memory above start (`collision2d_scaling_bench`, 1 worker, kB per body),
before -> after: rain of 1e4 3.33 -> 2.66, rain of 1e5 1.82 -> 1.63,
the pyramids of 9870 and 99681 boxes unchanged at 5.02 and 5.00 (their
contacts do not grow after the first frame); the same bits, the time
unchanged (alternating runs, median new/old: pyramid of 9870 0.983, rain
of 1e4 1.002 on 1 worker and 0.912 on 2, rain of 1e5 0.990). At first
(89f8a55) every freed block gave its pages back, and a World copied and
dropped, as the ROS services do for each edit, left the next copy to fault
its blocks in again: copying the pyramid of 9870 boxes three frames in
took 15.3 and 15.9 ms (medians of 15 copies) against 5.9 and 6.3 ms
before; since d45b069 only a block a buffer has outgrown gives its pages
back (6.6 and 7.5 ms). Tried and not kept: one outline shared by the
copies of a body, so that a scene's equal boxes hold a single one. Peak
memory fell by 4% (pyramid of 9870 boxes 5.04 -> 4.84 kB a body, rain of
1e5 1.63 -> 1.57), but copying that pyramid took 20 to 25 ms: without
the 20000 small blocks a copy used to allocate, glibc gave the freed
large blocks back to the system and each copy faulted them in again
(with glibc's thresholds fixed, 7.5 ms either way). What is left
on the pyramid is the layout: a contact point costs 296 bytes as a
point, 168 as a published contact and 128 in the rows, and a box of the
pyramid has 5.94 points, so 3.5 kB a body before the body's own arrays.
Even a point reduced to what persists (body ids, feature, two impulses,
the slip and the origin, about 100 bytes) plus its rows in double
precision would come to about 1.3 kB a body there, and Box2D v3 (in float) took 3.33 kB: the target of 1 kB a body
is out of reach of a double precision solver on scenes this dense in
contacts. Time, instructions and the cache: stepping from rest at the
defaults, ours ran 11.5, 11.8 and 12.1 thousand instructions a box a
frame on the base-20, base-60 and base-100 pyramids (callgrind); the
report at c7fdd08 timed ours at 1.55, 1.45 and 1.82 us a box, and Box2D
v3 at 0.83 us on the base-60 and 1.34 us on the base-100. Going to 5050
boxes, both engines lose time to memory, not to more work a box, Box2D
v3 more than ours. With a 2 MB last level simulated (cachegrind, 9
frames of the base-100 pyramid), the solve and relax passes took 40% of
the last-level read misses, the warm start 12%, packing the rows 9.5%
and publishing 6%: the rows, 3.8 MB for its 30000 points, do not fit the
2 MB second-level cache this host gives a core, and every pass streams
them again. On that pyramid Box2D v3 ran 39 million instructions a frame
in all, ours 61 million, 25 million of them in the soft passes: the time
ratio (1.36 in that report) is the instruction ratio (1.56) thinned by
both engines' waits on memory, and what ours runs beyond Box2D v3 lies in
the per-point stages of the twenty-ninth and thirtieth notes. Two
workers on the rain of 1e4 (`perf record`, 15 repetitions): both threads carried the same work, and each spent about
a tenth of its samples in the scheduler and `sched_yield`, waiting at the
passes' meetings between colours.

A thirty-second, on the same host (commit 2723716; scratch builds, not
committed, one that switched the solve order and the passes by
environment, one that timed the step's stages). Whether the tall
pyramids' drift at the defaults comes from the order of the passes: a
pass over colours is Gauss-Seidel in colour order, and a colour holds
manifolds of every height, so the weight of a stack reaches its bottom
only over many substeps. Stepping the stacks for 10 s at the defaults,
drift 1 s -> 10 s / largest penetration, mm (column, base-20, base-60,
base-100): the colours as shipped (greedy from the top down) 0.0471 /
6.02, 0.392 / 2.84, 6.59 / 10.9, 17.0 / 20.1; every manifold on the
point verbs one after another from the top down, which carries the whole
weight down in one pass, 0.0462 / 6.02, 0.402 / 2.84, 6.80 / 10.3, 29.3 /
19.5; the colours greedy from the bottom up 0.041 / 6.32, 0.327 / 2.85,
7.01 / 11.2, 28.1 / 20.2; one after another from the bottom up 0.044 /
6.02, 0.555 / 3.07, 8.32 / 10.6, 31.0 / 19.5. The order does not make
the drift: the base-60 pyramid drifts 6.6 to 8.3 mm in all four, and the
colours as shipped are best on the base-100. Nor do more relax passes
alone, at 40 Hz: one biased pass and two relax passes 0.874 / 6.02,
0.448 / 2.84, 4.87 / 8.83, 21.2 / 17.4; one and three 9.13 / 6.02, 1.08 /
2.83, 7.56 / 8.74, 18.0 / 15.5; two biased and one relax 0.00103 / 6.02,
0.218 / 2.83, 2.66 / 10.6, 46.7 / 20.0; two and two 0.0645 / 6.02, 0.236
/ 2.83, 2.58 / 9.50, 53.7 / 18.5. What drifts is the slow settling of the
contact springs as a whole (*Stacks against Box2D v3*), which no
ordering of one pass reaches. Two workers, by stage: the pyramid of 9870 boxes, 3
rounds of 1 and 2 workers, share of the 1-worker frame and the stage's
2-worker speed-up (medians): the solve 22.3% and 1.88, the relax 14.6%
and 1.84, the contact rows with their preparation 18.1% and 1.94, the
narrow phase 8.0% and 2.02, placing the rows 8.6% and 2.30, publishing
11.2% and 2.38; what scaled least was the broad phase's kept pairs when
rebuilt or paired exactly (4.4% at 1.1 to 1.4), moving the bodies with
the sweep (2.7% at 1.58), ordering the manifolds (2.5% at 0.98), preparing
the bodies (1.2% at 1.22) and the colouring, which is serial (1.0% at
0.86). The whole step's speed-up was 1.82, between 1.49 and 1.99 from
round to round. Ordering shared every digit's pass of its radix sort
between the parts, moving keys between the cores' caches on each; since
125468f each part sorts its own keys and the parts merge a share each
(the same order): on 2 workers the stage took 14.8 ms a run instead of
18.4, 1.28 times faster than on 1 worker (0.98 before).

A thirty-third, on the same host (commit fe249d1; callgrind on a scratch
driver stepping the base-100 pyramid at the defaults, frames 31 to 40,
not committed). A kept manifold follows its bodies' turns since it was
detected, and in a pyramid that has settled for a while those pass 1e-3
rad, where turn_of's series stopped: 18 thousand calls a frame went to
the library's sine and cosine, 1.76 million instructions. The series now
runs to 0.02 rad, past the largest turn a manifold is kept for (about
0.0173 rad), with the sine's x^11 term: 63.5 -> 61.7 million instructions
a frame (-2.8%); base-20 2.452 -> 2.456 million. The whole process (9
paired runs of 150 frames, pinned) took 0.956 of the time (0.83 to 1.19).
Drift 1 s -> 10 s and largest penetration unchanged to the digits
printed (mm): column 0.0471 / 6.02, base-20 0.392 / 2.84, base-60 6.59 /
10.9, base-100 17.0 / 20.1; the demo's soft-step golden hash moved, no
other. Where the base-100 frame's 61.7 million instructions go, against
Box2D v3's 39.9 million over the same frames: the warm start, solve and
relax passes 23.1 against 23.6 million (v3's include gathering and
scattering the bodies); everything else 38.6 against 16.3 million. Of
ours: adding each pair's points with last frame's impulses and noting
its manifold 6.7, the points' masses 4.8, the narrow phase with its kept
manifolds 5.1, publishing the contacts 3.9, the body passes about 4.3,
placing the rows 2.3, the broad phase 2.2, ordering and colouring 1.1;
of Box2D v3's: the narrow phase 4.8, preparing the constraints 4.0, the
pair updates and pair finding 4.1, finishing the bodies 2.1, storing the
impulses 0.43. No stage of ours is far beyond its share: the gap is each
point written three times (as a point, a row and a published contact) and
read back, which only the compact per-point record of the twenty-fifth
and thirtieth notes closes.

A thirty-fourth, on the same host (commit 1f28311, and two trials not
kept; scratch drivers, not committed). The first step toward that record:
the contact point kept two copies, its spring (one of the frame's two,
chosen by its masses) and its depth beside its gap; the spring now lives
once in the frame and the depth is read from the gap, 296 -> 272 bytes a
point, with the same bits. Peak memory above the empty world (one run
each, 1 worker): pyramid of 9870 boxes 5.02 -> 4.88 kB a body, of 99681
4.91 -> 4.77; the rain of 1e4 unchanged. The base-100 frames 31 to 40
took 616.9 -> 620.6 million instructions (the spring and the depth are
now worked out where they are read), and time a frame did not move past
this host's noise (6 alternating pairs pinned to one core, 0.86 to 1.06).
Two orders of the passes, measured over 10 s at the defaults (drift 1 s
-> 10 s / largest penetration, mm; the defaults column 0.047 / 6.02,
base-20 0.392 / 2.84, base-60 6.59 / 10.9, base-100 17.0 / 20.1): the
relax pass over the colours in reverse order made every stack worse
(column 1.07 / 8.07, base-20 0.415 / 3.62, base-60 27.0 / 12.2, base-100
388 / 25.1); a second relax pass held the base-60 pyramid better (4.87 /
8.83) but not the others (column 0.874 / 6.02, base-20 0.448 / 2.84,
base-100 21.2 / 17.4).

A thirty-fifth, on a new host (an AMD EPYC with 2 virtual CPUs; commit
3756614, and trials not kept; scratch builds, not committed). The point
drops its two effective masses, which are now worked out where they are
read (1 / k, the same bits): 272 -> 256 bytes a point. Peak memory above
start (`collision2d_scaling_bench`, 1 worker, kB a body): pyramid of
9870 boxes 4.89 -> 4.79, of 99681 4.77 -> 4.68, rain of 1e4 2.04 ->
2.01; the pyramid of 2016 boxes 1255.9 -> 1255.0 million instructions
over its 40 frames, and the time the same (10 paired whole runs pinned
to one CPU, new/old 1.004, 0.96 to 1.02). Aligning the point to a cache
line as well gave 0.985 on the pyramid of 9870 and on the rain of 1e4,
within the spread: not kept. Two workers on the rain of 1e4 over the
bench's default window (frames 61 to 110) gained little on this host:
3.9 to 4.0 ms a frame on 1 worker, 3.6 to 3.7 on 2 (over frames 61 to
260, 3.2 to 3.3 and 2.2 to 2.3), against 1.7 times on the pyramid of
9870 (11.3 -> 6.7 ms). It is not the host: a one-worker run beside a
copy on the other CPU took 0.98 to 1.03 of its time alone (5 pairs each,
rain and pyramid). A clock around each stage of the soft frame, over the
bench's 50 timed frames (ms in all, 1 -> 2 workers; a second run of each
within 10%): the whole frame 193 -> 169; detection 92.6 -> 75.6, of it
the broad phase 32.7 -> 29.8 (the rain's boxes keep leaving their
enlarged ones, so the grid is built every frame), the narrow phase 17.5
-> 12.6, adding and preparing the points 25.3 -> 18.0, posing the
outlines 3.0 -> 1.6; packing the rows 13.9 -> 19.1; the solve passes
29.2 -> 27.8, the relax passes 19.0 -> 16.4; moving the bodies 12.7 ->
9.2; publishing 15.9 -> 12.0; the bodies' preparation 4.4 -> 3.9. The
rain's frames then hold about a thousand manifolds in a few colours, so
a colour's share is some ten microseconds: in `perf record` the row work
of both threads came to 1.3 times that of one worker, and the second
worker waited at the colours' meetings for 45% of its time in the
passes. Handing work over is not what costs: the rain hands the second
worker about 35 jobs a frame, which it starts about 1 microsecond after
they are posted, and the calling thread waits 4.6 microseconds a job on
average for the other share to finish (a clock in the worker pool, all
110 frames). Tried and not kept: workers taking a colour's batches 8 or
64 at a time from a shared count instead of a fixed half each (same
bits; pyramid of 9870 on 2 workers 2.2 and 1.6 times slower, rain 1.4
and 1.2 times: neighbouring batches on two cores share the bodies' cache
lines); spinning 4096 or 2^20 pauses instead of 64 before a waiting
worker yields (rain on 2 workers, 8 pairs, 0.95 to 1.06); the passes
shared from 256 or 4096 coloured manifolds instead of 1024 (0.98 to
1.03, 0.91 to 1.03); packing on one thread below 16384 points instead of
2048 (10 pairs, median 1.02); the grid's pairs left in each part's list
for the broad phase's counting sort to scatter from, instead of copied
into one list first (same bits): over the 50 frames on 2 workers the
grid search with its copy went from 13.6 to 9.0 ms, but the sort from
4.4 to 12.0, serial or with each part counting and scattering its own
list (both cores then write the same groups' cache lines), the broad
phase 29.3 -> 29.2 in all.

A thirty-sixth, on the host of the thirty-fifth (commits a21e345 and
7291b55, the same core, and a trial not kept; scratch builds, not
committed). Where two workers lose
time on the rain of 1e5: a clock around each soft-frame stage, in ms
summed over the 25 timed frames (medians of 3 runs each, 1 -> 2
workers; the bench read 27.6 - 28.5 ms a frame on 1 worker and 17.0 -
17.7 on 2, 1.61 to 1.65 times): the soft frame in all 677 -> 436; detection
406 -> 275, of it the broad phase 163 -> 139, the narrow phase 72 -> 39,
adding and preparing the points 91 -> 51, posing the outlines 24 -> 10,
the mover boxes 21 -> 8; the bodies' preparation 32 -> 14; packing the
rows 29 -> 23; the solve passes 36 -> 24, the relax passes 21 -> 15;
moving the bodies 67 -> 37, with the velocity kicks 11 -> 7; placing
them 27 -> 12; publishing 50 -> 27. The broad phase is the stage that
does not share: a quarter of one worker's frame and a third of two
workers'; halved like the narrow phase it would make two workers about
1.8 times one. Within it (2 runs): the grid's pairs 85 - 87 -> 61 - 67,
sorting them 26 - 28 -> 19 - 23 (the counting and scattering are
serial), filling the grid 23 - 33 -> 16 - 19, classifying the boxes 18
- 22 -> 11 - 12, placing them 6.5 - 6.7 -> 3.4 - 3.5. For some minutes of this
session one virtual CPU ran the pyramid of 9870 boxes on 1 worker 1.4
times slower than the other (15.6 - 17.3 against 10.6 - 12.0 ms,
pinned) and 2 workers
took 9.0 - 9.2 ms instead of 6.8 - 7.1; minutes later both CPUs ran it
in 11.3 - 11.5 ms. The worker figures of a report depend on such spells.
Tried and not kept: the worker pool cutting each job into 2 or 4 shares
a worker, taken one at a time, so that a slower core takes fewer of
them (same bits). With both CPUs equal, 2 workers ran the pyramid of
9870 boxes in 7.7 - 8.2 ms with 2 shares a worker and 7.9 - 8.7 with 4,
against 6.6 - 6.8 with one (4 alternating runs); the rain of 1e4 1.09
and 1.10 times slower, of 1e5 1.07 times with 4: with one share each,
every stage gives each core the same bodies' records, which stay in its
cache from stage to stage.

A thirty-seventh, on the same host (commits 698aaaa and deca5a1; scratch
builds with clocks, not committed). The broad phase shares its sort: each
part of the grid search lists a pair under the part that owns its first
box (owners take shares of the box indices balanced on the boxes and the
last call's pairs), and each owner counts, places and sorts its own pairs
straight into the caller's list. The serial counting sort, the copy of
every part's pairs into one list and the buffer swapped with the caller's
list are gone, and one part takes the same path. Same pairs and bits.
Clocks over the rain of 1e5's 25 timed frames (ms, 3 runs each of 1 and
2 workers): the broad phase 166 - 177 -> 110 - 114 (139 on 2 workers in
the thirty-sixth), of it the grid search 85 -> 43 - 44 and the sort 31
-> 28, most of which is first writes to pair lists that grow with the
rain (a list grew in 5 of the 25 frames, 20 ms); the soft frame 725 -
829 -> 440 - 466. Whole processes against d11b226, alternating, both
CPUs checked equal: on 2 workers the rain of 1e5 took 0.957 of the time
(6 pairs, 0.88 to 0.99), the rain of 1e4 0.948 (6, 0.85 to 1.01), the
pyramid of 9870 boxes 0.992 (5); on 1 worker the rain of 1e4 1.008 (5,
pinned). Peak memory above start on 1 worker, kB a body: rain of 1e5
1.667 -> 1.594, of 1e4 2.632 -> 2.531, pyramid of 9870 4.784 -> 4.786:
the swapped buffer had kept a second block as large as the largest list
sorted (on the rain of 1e5 the enlarged boxes' 394 thousand pairs, 6.3
MB). What still shares badly on the rain of 1e4 is packing the rows
(ms over the bench's 50 timed frames, 1 -> 2 workers, 2 runs): 13.9 -
14.8 -> 20.2 - 20.3, of it placing the rows 7.1 - 7.7 -> 9.0, ordering
the manifolds 4.2 -> 5.1 - 5.2 and colouring them, on one thread, 1.7 -
2.0 -> 4.7 - 4.8: the colouring reads manifold notes that the other
core wrote while preparing its share of the points.

A thirty-eighth, on the same host (commit 714ffcd; scratch drivers and
clocks, not committed). Where the two-worker targets stand on this host.
Two threads handing one cache line back and forth took 159 to 557 ns a
round trip at different times of one session (the guest's two virtual
CPUs are placed anew by the host), while two threads of independent
arithmetic ran together as fast as one alone (0.36 - 0.39 s each, either
CPU). Alternating runs in a slow-link spell (484 - 557 ns): the rain of
1e4 took 4.71 - 4.82 ms a frame on 1 worker and 3.83 - 4.18 on 2 (1.13 -
1.24x), Box2D v3 5.45 - 5.53 and 5.80 - 5.86 (0.93 - 0.94x). With clocks
on the stages (frames 61 to 90, two runs each), no stage of the rain of
1e4 ran much faster on 2 workers in such a spell: moving the bodies, a
loop over them that no two workers write alike, 8.2 ms -> 7.2 - 7.4;
detection 41 -> 46; the solve passes 8.1 -> 12.3 - 13.1. A stage reads
records the other core wrote in the stage before. The body stages give
each worker half of the body indices, and a colour's rows (in pair
order) are split at half their count: on the pyramid of 9870 boxes
99.5% of the rows' body references fall in the share of the worker that
solves them, on the rain of 1e4 70% and of 1e5 53% (a scratch count over
the frames of a bench run). Splitting each colour at the body shares
instead would raise that to 99.8 - 100%, but put 80% (1e4) and 96% (1e5)
of a colour's rows on one worker: the rain's contacts lie among the
bodies that have landed, which fill a part of the index range. The pyramid of 9870 boxes
took 12.3 and 20.2 ms on 1 worker minutes apart, Box2D v3 9.5 and 15.8,
while the arithmetic test ran at one speed: memory-bound frames follow
the host's other load, so a single round decides little. Where the
base-100 pyramid's time goes on 1 worker (clocks, frames 61 to 180, one
core): the solve passes with the warm start 28%, the relax 18%, detection
26% (of it adding and preparing the points 13%, the narrow phase 7%),
packing the rows 12% (placing them 8%, ordering the manifolds 2.4%,
colouring 1.4%), publishing 9%, moving the bodies 3.5%. A colouring kept
from frame to frame, as Box2D v3 keeps its constraint graph, could save
at most the ordering and colouring, 3.8%; the stages that copy each
point (adding and preparing, placing the rows, publishing) take 30%,
which is what the compact per-point record would shrink. The tiny
scenes: the first frame of a fresh world took 2.5 to 8.2 times a later
one (medians of 20000 worlds, allocator thresholds fixed as the sweep
bench does), a share of the 30-frame timed run of 5.9% on incline, 4.9%
on incline_slide, 8.7% on bouncing_disks and 19.3% on bullet_wall
(incline's first frame: 18.7 thousand instructions, 56 allocations,
against 6.9 thousand a later frame). Without any of it, only incline
would have met its 0.75x (0.782 -> 0.736); bullet_wall would still take
0.98x Chipmunk 7's time. Tried and not kept: every pair of up to 8 boxes
tested as four rows of coordinates and one bit mask a box, with no branch
per pair; on bouncing_disks (6 boxes) it ran 3.78 million instructions
against 3.72 million over 6000 frames, the pair tests staying scalar.

A thirty-ninth, on the same host (commits 59f8ac7 and 04a14ce; clocks,
callgrind and scratch drivers, not committed). On the rain of 1e5 at
frame 60 and after, on 1 worker, the broad phase took 27% of the frame
and moving the bodies 22%, of which 7% went to the speed check for time
of impact: every substep it read every body's velocity, though the sweep
never ran (no body came near its reach). A body no contact touches gains
speed only from gravity within a frame, so since 04a14ce a bound at the
frame's start (its speed plus one frame of gravity, against its reach)
proves it stays slow, and each substep checks only the bodies a contact
touches (448 to 4480 of the 100001 over frames 20 to 60); every body is
checked as before when the bound fails for any, with toi On, or when
most bodies are touched, as in a pyramid. Same flags and bits. The rain
of 1e4's whole bench process: 1237 -> 1151 million instructions (-6.9%;
the check 95 -> 5 million, the frame's body pass 76 -> 91). Whole
processes against 71ea969, alternating (7 pairs, medians, CPU): rain of
1e5 0.959 on 1 worker (0.93 to 0.98) and 0.984 on 2 (0.93 to 1.15); rain
of 1e4 1.005 (0.99 to 1.04) and the pyramid of 9870 boxes 0.999 (0.97 to
1.03) on 1 worker. A world of a few bodies paid for the choice (the
two-body incline 1.7% more instructions a frame): since 51c7ff5 below 16
visited bodies the frame checks every body as before, and against 71ea969
incline runs +0.4%, incline_slide +0.2%, bouncing_disks +0.7% and the rain
of 1e4 -6.2% (1160 million). When the tall pyramids drift, at the defaults (a
scratch driver over 60 s, mm of the largest displacement since 1 s):
base-60 5.60 by 2 s, 6.38 by 5 s, 6.51 by 60 s, the largest a flank box
low on the pyramid moving inward while the top box had sunk 237 mm into
the contacts below it by 1 s; base-100 27.3 by 2 s (the top still
sinking), 16.7 by 5 s, 17.0 by 30 s. The drift is the first seconds'
settling, the slow vertical mode of *Stacks against Box2D v3*.

A fortieth, on the same host (commit ff056d6; callgrind, perf and
scratch drivers, not committed). Every frame counted each moving body's
type, shape and materials to choose the Auto effects, though only an edit
changes them: on the rain of 1e4 that census took 3% of the bench
process's instructions. Since ff056d6 it is kept until the next edit, and
a disk's spin is counted again each frame only where it decides rotation
(no friction, no dynamic polygon). Same effects and bits. Whole bench
processes, 1 worker, million instructions: rain of 1e4 1157.0 -> 1117.4
(-3.4%), rain of 1e5 9794 -> 9429 (-3.7%), pyramid of 5050 1431.1 ->
1419.0 (-0.85%); 300 fresh worlds of 30 frames: incline -1.2%,
incline_slide -1.3%, bouncing_disks +0.6% and bullet_wall +0.8% (their
frictionless disks were still counted each frame; since 479f055 only
while one spins, for -4.5% and -2.2%). Alternating whole
processes (CPU, medians): rain of 1e4 0.988 (15 pairs, 0.95 to 1.06),
rain of 1e5 0.947 (9 pairs, 0.82 to 1.12). Tried and not kept: batches
without their inverse masses (the lanes took each body's from the load
that already brought its velocity) and without their springs (chosen by
whether a body is fixed, as the point verbs choose), 1024 -> 896 bytes a
two-point batch and 704 -> 576 a one-point batch, the same bits; the
pyramid of 5050 boxes peaked 448 kB lower (89 of its 4.85 kB a body) but
ran 1431 -> 1460 million instructions, 27 million of them from carrying
the masses beside the velocities, and took 0.994 of the time (11
alternating pairs, 0.80 to 1.07): the passes are not limited by the
batches' bytes. How much an incremental broad phase could save on the
rain: of the 10000 bodies, 80 to 86% left an enlarged box (by 0.1 of its
size, as FatBoxPairs enlarges) each frame from frame 60 to 75, so re-pairing
only the boxes that left would spare at most a fifth of the pairing. Two
workers against one in alternating runs today: the rain of 1e5 1.70,
1.71, 1.51, 1.64, 1.73; the rain of 1e4 1.25, 1.24, 1.35, 1.63, 1.39.
Profiled with call stacks on 2 workers, the calling thread spent 60% of
its step in its shares on the rain of 1e4, about 30% waiting for the
worker (yields at a colour's end or a job's) and 8% in serial work (the
worker 79% at work, 16% idle); on the rain of 1e5, 76% in shares, 15%
waiting and 9% serial, of which the colouring 3.1 points and the touching
flags and sweep candidates 1.4.
"""
