"""The later profile notes (the nineteenth on): what a second worker and the
memory stream cost on the hosts that ran the reports. report_profile_notes.py
joins them to the earlier ones."""

PROFILE_NOTES_WORKERS = """A nineteenth, on a second host (commits 15ec9ca and 0556e24; scratch
drivers, not committed). The reports up to commit f8df314 ran on a host
that also calls itself "AMD EPYC"; this one is family 23 model 1, the
first Zen generation, which splits each 256-bit operation into two
128-bit halves, with 512 KiB of L2 a core and 8 MiB of L3 (the machine
line now says so). On it the build of commit f2e10b7 stepped the five
stacks at 2.04, 1.61, 1.68, 2.59 and 2.30 times Box2D v3's time (stack
bench, 5 rounds of 2 s; that report: 1.6, 1.36, 1.36, 1.74, 1.56), and the
row passes took 46% of the base-100 pyramid's frame (35% in the seventh
note). Whole processes stepping the base-100 pyramid for 120 frames,
alternating pairs, median ratios:
- The four-lane path is still the fastest here: the two-lane path took
  1.44 times its time and the scalar path 1.79 times (5 pairs each).
- Divisions do not bound the rows: each replaced by a reciprocal
  estimate refined twice (other bits) made the base-20 pyramid 7% slower
  (8 pairs).
- Bytes do, a little: 128 bytes of padding in each solver point cost about
  5% (10 pairs, 0.952), 40 bytes a lane in the rows about 6% (0.941), and
  aligning each body's solver state to a cache line nothing (0.994).
Commit 15ec9ca keeps the rows' flags (friction acts, kinetic, sliding) in a
byte a lane beside the body indices instead of in doubles: 144 -> 128
bytes a point of a two-point manifold, 192 -> 176 of a one-point one, the
same bits. The base-100 pyramid 0.928 (10 pairs); the base-20 pyramid
1.001 (its rows stay in cache); `collision2d_scaling_bench`, the pyramid of
9870 boxes on 2 workers 0.916 (8 pairs), the rain of 1e4 on 1 and 2
workers 0.978 and 0.985 with 1.4 and 1.7 MiB less at its peak. Tried after
it and not kept: the inverse masses read from the bodies' solver state
(already in the four-lane gather's loads) instead of the rows, 64 bytes
less a batch: base-100 1.009, rain of 1e4 1.02, pyramid of 9870 1.01; the
inverse inertias too, a third load a body: base-100 1.043.
Two workers on this host, at f2e10b7: the rain of 1e4 1.68 and 1.70 times
faster than one (two runs of `collision2d_scaling_bench` each), the pyramid
of 9870 boxes 1.57 (the report at f8df314, on the other host: 1.19 and 1.78). A
`perf record` of that pyramid on 2 workers finds both threads busy for the
whole run, each with about half of every stage: what the second worker
loses is its pace while both run (the L3 and memory they share), not a
stage left on one thread.

A twentieth, on the same host (commits ca83380, 3b83b1d and d41dd57). The
threads' samples in `perf record` of the rain of 1e5 bodies on 2 workers
(frames 60 to 80) showed what the calling thread still did alone while the
second worker waited: 6.7% of all samples, about 13% of its own. The step
report's kinetic energy read every body's cold record in one loop (2.2%),
the polygons' vertex offsets were laid out again every frame though only
an edit changes them (1.4%), and the broad phase listed the classified
boxes, walked them for the grid's entry count and sorted each body's pairs
on that thread (2.7%). The energy is now summed in blocks of 512 bodies
that the workers read in parts (the block sums added in order: the same
bits for any worker count), the offsets are kept until an edit, and the
broad phase counts each part's boxes and entries, then writes each part's
lists from where the parts before it end. `collision2d_scaling_bench`,
whole processes, alternating pairs, median new/old against de25f51: the
rain of 1e5 on 2 workers 0.947 (8 pairs, every one below 1) and on 1
worker 0.978 (6), the rain of 1e4 on 2 workers 0.965 (10), the pyramids of
9870 and 99681 boxes on 2 workers 1.008 and 1.000; peak memory unchanged.
At the rain of 1e4 alone the first of these changes measured nothing
(1.0006, 12 pairs): there the serial stages were under 2% of the samples.
Two heap effects on the way: a list of every body's energy (0.8 MiB for 1e5
bodies) raised the pyramid of 99681 boxes' peak on 2 workers by 4.7 MiB,
and letting the grid lists and their entry offsets grow in turn (one loop
instead of two) raised the 1-worker rain of 1e5's by 5.4 MiB; the block
sums and the old order of growth left both peaks as they were. Tried and
not kept: the rows' softness as a flag a lane choosing one of the frame's
two (contacts with a body that cannot move are the stiffer), 64 bytes
less a batch (RowBatch 1024 -> 960, the same bits): the base-100 pyramid
0.983, the base-20 1.015 (10 pairs each), the pyramid of 9870 boxes on 2
workers 0.970 and the rain of 1e4 on 2 workers 1.004 (8 each), within this
host's spread; the two selects a lane cost about what the loads saved.

A twenty-first, on the same host (commits 10f7c1a, 6321686 and a8c5669;
stage timers in a scratch build, not committed, frames 60 to 65 of the
rain of 1e5 and 4 to 13 of the pyramid of 9870 boxes, as the scaling
bench times them). In the rain the passes over every body took about 70%
of a frame, and one alone a quarter: the substeps moved each body on its
160-byte record, position and velocity, four times a frame (37 ns a body
and substep, about what streaming two lines of the record in and out
costs here). The poses now stay in frame_position_ and frame_theta_ and go
onto the records once a frame (or before a sweep reads them); loading the
velocities joins the pass that resets each body's motion, and storing
them, the finite-state check and placing the poses are one pass; a
mover's box is read from its outline just laid out, not from its vertices
turned again. The same bits (golden hashes). In-process (timers on), the
first commit took the rain of 1e5 from 58 to 44 ms a frame on 1 worker
and from 36 to 26 on 2.
`collision2d_scaling_bench`, whole processes, alternating pairs, median
new/old against 18bbce0: the rain of 1e5 on 1 worker 0.787 and on 2
0.730 (8 pairs each; peak 194.1 -> 191.1 and 210.3 -> 203.6 MiB), the
rain of 1e4 on 2 workers 0.925, the pyramids of 9870 and 99681 boxes on 2
workers 0.950 and 0.945 (8 and 6 pairs; peak +0.7 and +1.5 MiB, the two
new arrays' 17 bytes a body); the base-20 stack 0.990 (8 pairs).
What two workers still lose, per stage (1 worker / 2 workers): on the
pyramid of 9870 boxes the row passes scale 1.82 to 1.89, the narrow phase
1.5 to 1.6, publishing 1.54, filling the rows 1.37, ordering the
manifolds 1.1 and colouring them 0.6 (one thread, reading what two
wrote). A `memcpy` of 64 MiB copies 16.1 to 16.8 GB/s on one thread here
and 21.0 to 23.1 on two (1.3 to 1.37 times): a stage that streams its
data from memory cannot go much faster on the second core, and at these
sizes filling, publishing and the narrow phase do. The 1.7 times asked
of 2 workers on the large scenes needs fewer bytes a contact point, not
more sharing. The same shows one thread's way: from the base-20 pyramid
to the base-60 one, filling the rows grows from 3% to 10% of a frame and
publishing from 3% to 8%, as base-60's point layouts (about 9 MB) pass the
8 MiB L3 while Box2D v3's 1830 boxes (about 7 MB) stay in it; that is
where its ratio (2.5 times) parts from base-20's and base-100's. Tried
and not kept: marking the bodies for the sweep where their velocity for
the substep is set (0.985, 10 pairs: most of the rain's bodies touch
others through speculative contacts, so the marking pass stayed); a
software prefetch of each colour's next batch while filling the rows
(filling 9.8% -> 8.9% of base-60's samples, frame times within the
spread); transparent huge pages for the whole process, as in the
sixteenth (the pyramid of 99681 boxes within the spread on 1 and 2
workers).

A twenty-second, on the same host: how the core is built. catkin builds
the core as a shared library, compiled position-independent, and GCC then
assumes any of its global functions may be replaced at load time: it
calls each through the PLT, even from its own file, and inlines none
where it is called. Measured at 63516d4 (whole processes, alternating
pairs, median ratio), a scratch program stepping the report's
heavy_on_light_1e2 scene at the defaults ran 1.174 times as long on a
shared core as on the static one the benchmarks link (10 pairs), the
base-20 pyramid 1.020 (8): the ROS node ran small worlds slower than this
report measured. `-fno-semantic-interposition` on the core (nothing
replaces its functions) brought the shared core to 1.059 of the static
one, and link-time optimisation on top to 0.949. Both are now in the
build: the flag always, link-time optimisation in Release builds with GCC
(`COLLISION2D_LTO`, on by default); a static core keeps plain code beside
(fat objects), so the tests link as before and only the report's three
benchmarks take the whole-program pass. New against old, the shared core
as catkin builds it: heavy_on_light_1e2 0.802 (10 pairs), the base-20
pyramid 0.932 (8), the base-100 pyramid 0.981 (6); the static core in the
benchmarks: heavy_on_light_1e2 0.928 (10), `collision2d_stack_bench` on
the base-20 pyramid for 20 s 0.982 (10) and on the base-100 one 0.986 (6),
`collision2d_scaling_bench` on the rain of 1e4 with 2 workers 0.980 (6,
peak 41.0 -> 40.9 MiB). The same bits: the golden hashes pass in both the
shared and the static build. No function outside the four-lane rows holds
an AVX2 instruction in the optimised benchmarks (checked in their
disassembly), so the rows' run-time choice still guards them.

A twenty-third, on the same host: small worlds, whose manifolds all go to
the point verbs (a frame of one or two manifolds has no colours, and a
colour's few leftovers stay off the rows). Profiled at f892a92 on
heavy_on_light_1e2 at the defaults (4 substeps), those verbs took about
half of a 3.4 us frame, some 100 ns a manifold solve. Each pass computed
a point's anchor offset twice (for its gap, then for its friction's pull),
through a function the World's file could not inline, and the 2x2 LCP of
a manifold's normals stayed a call after link-time optimisation. Commits
6391de5 and 49c8c6e read the offset once a pass and inline both, and the
relax pass no longer divides by a softness scale of exactly one, as the
rows already did; the same bits (the golden hashes pass). Whole
processes, link-time optimised as the report's benchmarks, alternating
pairs: heavy_on_light_1e2 0.931 (10 pairs) and then 0.975 (10);
bouncing_disks and incline at 1 substep (one-point manifolds, or a frame
the solve is a small part of) 0.992 and 0.995 (8); the base-20 pyramid
in-process 0.985 (8). Tried and not kept: every manifold of a small frame
on a row of its own (colours from one manifold up, batches from one
lane): heavy_on_light_1e2 ran 1.6 to 2.2 times as long on the four-lane,
the two-lane and the scalar path alike (3 runs each, built without
link-time optimisation), since a batch costs
its packing and four lanes' work whatever it holds. Where the incline's
sleeping run loses: this report times 30 frames of a fresh world, and in
a scratch program a fresh world's first frame took 4.2 us against 1.1 us
for the frames after it (medians of 3000 worlds): it sizes about fifty
buffers for the first time. That adds about 0.1 us to each timed frame
of the tiny scenes.

A twenty-fourth, on the same host: three changes that keep the golden
hashes, each measured as whole processes linked as the report's
benchmarks, in alternating pairs. Commit 51e3563: the publish of a soft frame took each
point's impulses from its row into the point, carried its slip there and
copied it into the contact; nothing reads the point after the publish,
so it is now only read (the base-100 pyramid, 60 frames then 120 timed,
0.991 of the commit before, 10 pairs: within the host's spread). A
profile of that publish put a third of its time on the load of each
point's row, which lies in colour order while the publish goes in point
order; prefetching the row twelve points ahead gained nothing (1.007, 10
pairs), so it was not kept. Commit f862c22: a kept manifold's check of
how far its pair had moved took the library's cosine and sine of body a's
angle at the origin, every frame; the offset now, turned back by a's turn
since then (whose cosine and sine the check already had), lies in the
frame the offset then is in. The length is the same up to rounding, so
only a decision within an ulp of `contact_reuse_distance` could change;
the golden hashes are unchanged. Commit 04f760d: GCC zeroed the step's and
the frame's reports (104 bytes each) with `rep stos`, whose start-up cost
a profile of the incline put at 2% of its frame; the core now asks for
vector stores up to 256 bytes (`-mmemset-strategy`, where the compiler
takes it). Figures: incline at 1 substep, sleeping on, 40000 fresh worlds
of 30 frames, 0.965 after f862c22 and 0.984 after 04f760d (10 pairs
each); incline_slide after f862c22 0.947 (8); the base-20 pyramid, 1500
frames, after 04f760d 0.978 (8). Measured in one process (the frames
only, medians of five runs of 100000 worlds), the incline's frame went
from 1214 to 1197 ns across the three: the whole-process ratios include
building the worlds, and this host's spread between runs is about 3%.

A twenty-fifth, on a third host (Intel Xeon, family 6 model 207, 2 MiB of
L2 a core and 260 MiB of L3; measured at commit 5970544 with scratch
instrumentation, not committed). On it every stack is within 2x Box2D v3's
time, and two workers give the pyramids 1.8 to 2 times one worker's speed,
but the rain of 1e4 only about 1.4. Summed over its 110 frames (60 of
warm-up, 50 timed), each stage's time on 1 worker over its time on 2,
medians of 5 alternating rounds: the narrow phase 1.63, placing each
pair's points 1.63, the relax 1.66, the biased solve 1.56, publishing
1.47, adding the manifolds' points 1.49, but the broad phase 1.19 (within
it, filling the grid 1.01 and sorting the pairs 1.02), packing the rows
1.20, moving the bodies 1.27 and the other per-body passes 1.16 to 1.43;
the frame 1.44. The per-body passes of 1e4 bodies last 10 to 30 us, and an
empty job handed to the second worker costs 0.5 to 0.7 us (a scratch
program timing 20000 of them), so the split itself is not what they lose:
both threads' shares of the pool's jobs summed to 170 and 166 ms, and the
calling thread waited for the other 10 to 17 ms in all. In `perf record`
(2 workers, calling thread only, 1114 samples) 28% of the samples fell
outside the pool's jobs: packing the rows, whose greedy colouring is
serial (about a tenth of them), the broad phase's serial passes (its
pairs' counting sort, the grid's prefix, clearing its counts; about a
sixth), mapping grown buffers' pages with `madvise` on the calling thread
(about an eighth), and yields while the other worker finished (a fifth).
Each is a few percent of the frame; making the colours persist from frame
to frame, as Box2D v3 does, would change the solve order and so every
golden hash. This host's speed also drifts more than the others': the rain
of 1e4 on one pinned worker took from 4.7 to 10 ms a frame within an hour.
Memory, from the buffers' sizes after the fifth frame of the pyramid of
99681 boxes (596302 contact points in 298151 manifolds, 5.98 points a box;
526 MB above the empty process at its peak): the frame's contact points
177 MB (296 bytes each), the published contacts 100 MB (168 bytes), the
soft step's rows 76 MB (128 bytes a point), the narrow phase's manifolds
31 MB (104 bytes a pair), the bodies 16 MB (160 bytes) and the rows' notes
10 MB. About 660 bytes go to each point every frame, some 3.9 kB of the
5.3 kB a box: what one compact record per point, built at detection and
read back by the rows, would shrink.

A twenty-sixth, on the third host (commits f797a6b and 090a66c, and trials
not kept; scratch drivers, not committed). The four-lane solve of a
two-point batch copied the batch's normal, lever arms and inverse masses
into the lane beside the two gathered bodies, more values than the 16
vector registers hold, so the compiler kept the copies on the stack. Read
from the batch where they are used instead (f797a6b), the solve is 716
instructions, down from 745, with 134 stack accesses, down from 154; the
base-100 pyramid on 1 worker took 0.964 of the time (9 alternating runs,
0.81 to 1.00). Not kept, on the same pyramid: the same file compiled for
AVX-512VL (32 vector registers, no fused multiply-adds) took 1.23 of the
time (9 runs, 1.13 to 1.49) with nearly as many stack accesses; GCC's
register-pressure scheduling on that file 1.03 (7 runs, 0.75 to 1.09);
applying an impulse to a copy of the velocities only, instead of a copy of
the lane, 1.15 (7 runs, 1.12 to 1.17); writing the bodies back by masked
stores of transposed rows 1.01 (9 runs, 0.88 to 1.13). The tiny scenes
spend their frame in some twenty stages; the largest, about a quarter of
bouncing_disks' frame, was the broad phase of five disks and a ground,
which checked their boxes against enlarged ones every frame before testing
the 15 pairs. A few boxes are now paired directly, each box's usability
checked once (090a66c): bouncing_disks at 1 substep took 0.941 of the time
(9 alternating runs of 180-frame worlds pinned to one core, 0.93 to 0.96),
bullet_wall on the Fx2D order 1.005 (1.00 to 1.01). In the sweep bench's
paired runs, whose worlds last 30 frames, bullet_wall's Fx2D 1x2 took 1.03
to 1.05 of its time at 1eabba5, the added time spread over stages neither
commit touched. Either commit alone gave 1.05 to 1.06, while an unused
function added to 1eabba5's core left its time as it was; the cause was
not found. Two workers: the host's two virtual CPUs are separate cores
(two pinned loops of independent multiplies took 1.317 and 1.325 s
together against 1.316 and 1.350 s alone). Profiled with call stacks on
the rain of 1e4, 28% of both threads' samples were in yields and the
scheduler: two threads busy 72% of the time give 2 x 0.72 = 1.44, the
speed-up the rounds measure; the calling thread spent 11.6% of its samples
waiting at the solve's colour barriers. That frame had 8 colours of mostly
one-point (disk) batches, 1259 and 1233 in the first two and 268 to 471 in
the other six, and no overflow. Sleeping after 65536 yields instead of
1024 changed nothing (0.991, 12 alternating runs, 0.87 to 1.12), and
cutting plain jobs into four chunks a worker, taken in turn, was slower
(1.06, 12 alternating runs, 0.73 to 1.13).

A twenty-seventh, on the third host (commits c17f42d and b139ffe, and
trials not kept; scratch drivers and timers, not committed). Counted with
callgrind on a driver stepping 180-frame worlds, bouncing_disks (soft
step, 1 substep) ran some 6.8 thousand instructions a frame and
bullet_wall (Fx2D, 1 substep) some 3.2 thousand, spread over twenty-odd
stages. Two of them did work a frame did not need. A frame that visits
every body posed every polygon, the static ground too, though only an edit
moves a static body: statics are now posed once per edit (c17f42d, with a
test that a floor moved between steps is met where it was moved to). The
few-box broad phase read each box as a struct and tested usability per
pair; it now copies the boxes once, an unusable box as an empty one
(b139ffe, in four arrays; its instructions 63.8M -> 49.6M over 90000
frames of bouncing_disks; 3173286 keeps Aabbs and their overlap test, for
601.7M in all instead of 596.3M). Both together: 623.2M -> 596.3M
instructions; bouncing_disks took 0.947 of the
time (9 alternating runs pinned to one core, 0.89 to 0.96), bullet_wall
0.974 (0.95 to 1.07). Not kept: testing six values finite at once by
summing each times zero cut bouncing_disks' instructions by 1.6% and its
time to 0.975 (0.96 to 0.98), but bullet_wall took 1.012 (1.00 to 1.02):
the sum's chain of dependent adds costs more than well-predicted branches
in a two-body frame. Testing each box against a fixed eight slots into a
bit mask added 9% of instructions. Reusing the last frame's colouring when
a frame has the same manifolds in the same height order (hash-neutral by
construction) never applied: on a pyramid of 78 boxes under a rain of 60
bodies, 0 of 240 frames qualified at 1 and at 2 workers, because
manifolds at one height swap places whenever their float keys move by a
last bit. On the base-100 pyramid (1 worker, alternating runs): padding
each contact point from 296 to 400 bytes took 1.083 of the time (7 runs,
1.04 to 1.28), the price of the point's size that a compact record would
save; transparent huge pages for the whole process took 0.980 (7 runs,
0.94 to 1.01) for 17% more peak memory (33088 KiB against 28156); 1024
spins before a worker yields, instead of 64, took the rain of 1e4 on 2
workers 1.079 (9 runs, 0.93 to 1.27). Stage timers on the rain of 1e4
(110 frames, microseconds a frame, 1 worker -> 2): collide 1347 -> 940,
of which the broad phase 579 -> 416; solve 501 -> 330; relax 337 -> 218;
move and sweep 397 -> 276; pack 209 -> 185 (its serial colouring 37 ->
51); publish 134 -> 83; in all 3235 -> 2240 (1.44x). The broad phase is
the largest stage: the rain's boxes leave their enlarged boxes every
frame, so the grid pairs all of them each frame, where Box2D queries again
only the boxes that moved out. Memory bandwidth is not the limit: two
persistent threads streaming 1 to 256 MB of arrays took 0.47 to 0.52 of
one thread's time.

A twenty-eighth, on the same host (commit ac3d9f0, and trials not kept;
scratch drivers and timers, not committed). In the report at b139ffe two
workers stepped the rain of 1000 bodies in 0.50 to 0.70 ms a frame against
0.41 to 0.61 on one. A timer around the contact publish, that frame's only
shared stage (1024 to 1489 points), read 80 to 93 us a frame on 2 workers
against 17 to 18 on one thread: the worker had gone to sleep since the
last frame, and the caller waited for it to be scheduled again. Since
ac3d9f0 the shares after the caller's are taken by whichever thread asks
first, so the caller takes a sleeping worker's share itself: 35 to 36 us.
`collision2d_scaling_bench` on 2 workers, whole processes alternating with
the build before, median ratios: rain of 1000 0.870 (41 pairs), 2000 0.984,
3000 0.946, 1e4 0.993, pyramids of 990 and 9870 boxes 1.003 and 0.996.
Tried first and not kept: no sharing below 2048 or 4096 points instead
(the rain of 1000 0.812 and 0.847, but the rain of 2000 1.041 and of 3000
1.085 at 4096: a size rule trades one scene for another); waking the
workers at the start of each step (0.984, 41 pairs); handing a job over
through atomics alone, without the mutex, which cut an empty job's round
trip from 0.7 to 1.0 us to 0.4 us but measured 0.999 on the rains of 1000
and 3000 (41 pairs each; a cache line crosses between the two virtual CPUs
in 140 to 170 ns, half a measured ping-pong); and, on the rain of 1e4,
cutting each share into eight chunks that an idle thread may take: the
caller's shares took 474 ms and the worker's 372 ms over 160 frames, but
two worlds stepped in alternate frames in one process, chunks on and off,
gave 1.011 and 1.001 (300 pairs each), the pyramid of 9870 boxes 1.001.
There the two threads are simply slower together: the shared stages ran
1.37 times as fast on 2 workers as on 1 in that run, and the serial rest
took 0.46 ms of a 4.5 ms frame. A caution for every two-worker figure here: one
worker stepping the rain of 1000 took 0.40 to 0.42 ms a frame while
another process spun or yielded on the other virtual CPU, and 0.48 ms
while that CPU idled.

A twenty-ninth, on the same host (commit 8fb374e, and trials not kept;
scratch drivers, not committed). The time target's paired rounds build a
fresh world for each repetition of 30 frames, so what a world's first
frame allocates is part of the figure. Chipmunk 7 1x8 on bullet_wall took
0.26 us a frame in some rounds and 1.2 to 1.7 us in others (the paired
ratio 0.22 to 2.1 in one run of 7 rounds); `perf record` of the slow case
had 20% of its samples in page faults and 9% in memset. glibc raises its
mmap threshold when a mapped block is freed and trims the heap's top, so
whether a new world's blocks are reused or faulted in again depends on
what the process freed before. Since 8fb374e the sweep bench fixes both
thresholds for the run: two runs of 7 rounds gave 1.079 to 1.088 (one
first-round outlier at 0.769). Our own first frame costs too: a fresh
bullet_wall world's first frame took 1.77 us against 0.30 us for the
later ones (33 allocations, 2 KB), 17% of a 30-frame run; bouncing_disks
1.53 against 0.48 us (35 allocations), 7%. Reserving those buffers as the
bodies are added would move that time to building the world, not save it;
it is not done. Not kept: solving a manifold's two normals one after the
other, as Box2D v3 does, instead of as a 2x2 block, in the rows and the
point verbs. On the base-100 pyramid (1 worker) it took 1.015 of the time
(7 alternating runs, 0.69 to 1.35), so the block's four divisions are not
what limits the pass, and over 10 s at the defaults (drift 1 s -> 10 s /
largest penetration, mm) the column went from 0.047 / 6.02 to 2.26 /
8.17, base-20 0.392 / 2.84 to 0.367 / 2.60, base-60 6.59 / 10.9 to 7.43 /
7.63: the block is what holds a column. Not tried: an eight-lane pass on
512-bit registers; eight independent chains of 512-bit multiplies did
1.18 times the lane operations a second of 256-bit ones on this host, and
divisions 1.00. Memory at the peak of the pyramid of 9870 boxes (massif,
1 worker, commit e69e437): 94.4 MB of heap, of which contact points 36.8%,
published contacts 20.9%, rows 15.9% and manifolds 6.5%; each is reserved
at twice its size so that a count creeping up seldom reallocates, and only
the part in use is resident (the report's 5.4 kB per body). The base-100
pyramid on one core ran 7.4 to 11.2 ms a frame in consecutive runs of one
build today, so only the memory figures here are exact. The tiny scenes
have slow spells too. In the paired rounds of the report at f0abd37 our
incline run (soft step 1x2, sleeping on) took 1.09 to 1.18 us a frame in 6
of 7 rounds and 0.59 us in the seventh, and the incline and elastic_gas
time targets read missed (0.60x and 0.69x in the report before, 0.627x
and 0.713x in the one after, at 5d4b221). Rounds of
the two builds alternated afterwards, 28 each (8fb374e and e69e437): ours
took 0.59 us in 25 and 22 rounds and 0.97 to 1.16 us in the rest, Chipmunk
7 0.98 us in 22 and 25 and 1.19 to 1.51 us in the rest. A spell slows one
run and not the next (a tenth of a second later), ours by about 1.9 times
and Chipmunk's by 1.2 to 1.5, and it is no build's doing.
"""
