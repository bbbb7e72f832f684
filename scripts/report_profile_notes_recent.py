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

A forty-second, on the same host (commit 887f61f, and trials not kept;
scratch drivers stepping `make_stack_scene` at the defaults, and scratch
changes to the core, not committed). Where the base-60 pyramid's drift (1 s
-> 60 s: 6.51 mm) comes from: the box that moves most is on the flank (x =
24 m, y = 7.5 m), 6.59 mm inward by 10 s, and the largest drift was 5.60 mm
by 2 s already. While the top box sank 277 mm into the contacts (0.4 s),
that flank box slid 24.1 mm outward, was back at 2.8 mm by 0.5 s and swung
with the stack's vertical bounce (about 0.6 s a period) until the top box
came to rest, 232.3 mm down, by about 1.5 s. Counted from 2 s the same run
drifts 2.47 mm, from 3 s 1.67: a slower mode is left, a low flank box (27.5
m, 4.5 m) creeping inward 0.90 mm from 5 s to 60 s while its tilt falls from
1.8e-4 to 2e-6 rad. That creep did not change with the slop (1e-4 m: 1.66
mm, 1e-2 m: 1.65, from 3 s to 30 s) or without kept contacts (reuse distance
0: 1.66), and it halved with each doubling of the passes (2 passes 0.83 mm;
60 Hz, damping ratio 15 and 4 passes 0.40): it is the passes' slow
convergence, not the friction model. Three ways to converge faster in a
pass, measured (drift 1 s -> 10 s in mm, base-60 / base-100; the defaults
6.59 / 17.0). Over-relaxing the normal block (its new impulse x + w (y - x),
kept >= 0) in the relax pass: w 1.5 4.51 / 22.5, w 1.7 4.43 and w 1.9 5.81
on base-60; in both passes, w 1.2 5.11 and w 1.5 4.92 on base-60. Friction
before the normals in both passes, over 60 s: base-20 0.408 -> 0.224,
base-60 3.34, base-100 22.8 (at damping ratio 12: 0.332, 3.43, 16.8, and the
column 0.192 as without it at that ratio); but a box at rest on a 0.40 rad
incline (mu_s 0.5, mu_k 0.3) at 1 substep slid away: in its first frame the
biased pass's friction met a zero normal impulse, the box slipped 1.04 mm,
past the 1 mm slop, and the kinetic cone took over. With friction first in
the relax pass only (10 s: base-20 0.490, base-60 4.77, base-100 15.4) that
box slid too: the relax's normals, solved last, turn it on its corners and
leave it slipping; friction first in the biased pass only took base-100 to
53.9. The relax pass as normals, friction and normals again, with the
friction clamped into the cone of the new normal impulses (which may fall
under it), held the incline and met every unit test but the soft step's
golden hashes; over 60 s: column 0.047, base-20 0.308, base-60 3.86,
base-100 12.5 mm (largest penetration at the end unchanged: 6.02, 2.82,
8.70, 14.6 mm). It costs a third normal solve a substep: frames 31 to 40 of
the base-100 pyramid ran 714 million instructions against 610 (+17%), and
the scaling bench's pyramid of 5050 boxes (1 worker) took 1.14 to 1.26 times
as long in 7 alternating runs pinned to one core. No target moves to met and
the base-100 time target moves away, so it is not kept. The normals again in
both passes drifted 5.41 / 33.9, in the last substep's relax only 5.86 /
16.2, and friction, normals, friction in the relax 6.21 / 21.1. Nor does the
contact's damping ratio reach both at 40 Hz: 8 gave 5.80 / 25.6 and 12 gave
7.97 / 12.9 (at 35 Hz: 9.48 / 218 and 7.84 / 130). Two workers on the rain
of 1e4 (`perf record`, 10 repetitions): the calling thread spent 19% of its
samples yielding at the passes' meetings and the worker 12%, and the
worker's share of the solve rows took 8.0% of the samples against the
caller's 5.1%; a `sched_yield` costs 1.27 to 1.35 us on this host and a
`pause` 19 ns, so a waiting thread yields after about 1.2 us of spinning.

A forty-third, on the same host (commit 34cf7da; scratch drivers stepping
`make_stack_scene` for 10 s, and scratch changes to the core, not committed;
drift 1 s -> 10 s and largest penetration the step reported, in mm, 4
substeps throughout). Why base-100 drifts 17.0 mm at the defaults: its top
box sank 930 mm into the contacts by 0.6 s, was 653 mm down at 1 s, 535 at
1.3 s and 688 at 1.9 s, and rested 644 mm down from about 4 s (a period of
about 1.25 s, each swing some 0.4 of the one before). At 1 s it was passing
its resting height, so the drift is small by phase: counted from 0.9, 1.1,
1.2 and 1.5 s it is 101, 59.8, 99.1 and 56.8 mm, from 2, 3 and 5 s 36.6,
5.98 and 1.76. The stack bench now prints the sway (the largest displacement
since 1 s at any frame): 119 mm for ours, 196 for Box2D v3 (drift 108) in a
10 s check. The figure is not fragile: 39.9 and 40.1 Hz, damping ratio 9.9
and 10.1 gave 16.7 to 17.5 (base-60 6.66 to 6.80). More passes ring longer:
at 40 Hz 2, 3, 4 and 8 passes drifted 53.7, 64.0, 68.7 and 71.2 (with 8 the
top box was 71 mm above its rest at 1 s; the single under-converged pass
damps the slow mode), and a high damping ratio with converged passes creeps
in (8 passes, damping ratio 30: 578 mm down at 1 s; 100: 309 mm). With 1
pass, damping ratio 20 and 40 gave base-60 12.3 and 48.9, base-100 40.5 and
120. Stiffer contacts need more passes (base-60 / base-100 drift;
penetration in brackets): 1 pass at 45, 50 and 60 Hz drifted 5.48 / 122,
5.78 / 228 and 44.3 / 200 (the column's penetration 5.02, 4.58, 4.39 against
6.02 at 40 Hz). At 60 Hz and damping ratio 15, 2 passes 1.95 / 8.25 (4.60 /
8.58), 3 passes 1.62 / 4.70 (3.91 / 7.79), 4 passes 1.28 / 3.94; at damping
ratio 10, 4 passes 0.858 / 19.6; at 20, 4 passes 1.74 / 4.86; at 40 Hz and
20, 4 passes 7.18 / 10.5. A second pass took 1.36 to 1.49 times as long on
base-100 at 60 Hz (user time, 3 alternating pairs), which would take the
base-60 pyramid (1.48x in this report) past twice Box2D v3's time: no
setting measured at 4 substeps meets both tall drift targets within the time
target. Tried and not kept: the static contacts at 60 or 100 Hz instead of
twice the contact's 40 (6.68 / 18.3, 6.64 / 16.7); biased and relax passes
in different numbers (at 40 Hz, 2 relax passes 4.87 / 21.2, 3 relax 7.56 /
18.0, 2 biased 2.66 / 46.7; at 60 Hz and damping ratio 15, 3 biased and 1
relax 1.32 / 27.8, 1 biased and 3 relax 5.78 / 13.9); 8 passes in the first
second only (base-60 0.464, but base-100 71.2: it settles again when the
passes drop); the relax pass over the colours in reverse order, a symmetric
sweep (column 1.07, base-60 27.0, base-100 388; both passes reversed 0.041,
5.99, 21.4; the biased pass only 0.287, 18.8, 193); a share of the spring's
load carried over from the last frame as a push in the biased pass (a
fraction a of the compression that the frame's warm-start impulse would
hold, so a steady load needs 1 - a of the compression): a = 0.3 column 0.172
(penetration 4.75), base-20 0.333, base-60 6.97, base-100 84.6 (16.6); a =
0.5 the column drifted 2.69 (at a = 1 it winds up, as an earlier note
found). Where the serial stages stand: over frames 31 to 40 of base-100 on 1
worker (callgrind, 610 million instructions) the greedy colouring took about
1.0%, ordering the manifolds 2.3% and placing the rows 3.9% (both shared
among workers); the pyramid of 9870 boxes has 7 colours (six of 4611 to 4959
manifolds, one of 328) and the scaling bench's rain of 1e4 2 colours of 994.
On the small scenes a frame of incline (soft step, 1 substep, sleeping on,
300 fresh worlds of 30 frames) ran 6.76 thousand instructions, the pair
finding 17% of them inclusive and no function above 4.4% on its own.

A forty-fourth, on the same host (commit b5c1cd1; scratch changes to the
core and drivers, not committed). A spring stiffened per manifold so that
the load it carried last frame compresses it at most a target depth (its
mass scale recomputed for that stiffness, the push-out rate kept), stack
bench over 10 s, drift 1 s -> 10 s / largest penetration, mm, against the
defaults' column 0.047 / 6.02 and base-60 6.59 / 10.9: a target of 5 mm
gave the column 2.18 / 4.67 and base-60 7.04 / 8.93; 3 mm 2.95 / 4.62 and
141 / 9.28; 1 mm 33.9 / 4.71 and 1280 / 15.2 (base-20 unchanged at 0.392 /
2.84). As the stiffness by load in the stack notes, a stiffness that
follows last frame's load winds up the tall stacks. Sharing the soft passes
among workers from 256 coloured manifolds instead of 1024: the rain of 1e4
on 2 workers took 0.994 of the time (12 alternating whole processes, 0.91
to 1.05). Writing each body back from the four-lane rows as one 32-byte
store of its transposed row (v.x, v.y, omega and the moved.x it was
gathered with), so that a later colour's gather loads what one store wrote,
and the friction flags' bytes as one read-modify-write instead of a branch
a lane: frames 31 to 40 of base-100 on 1 worker ran 599.0 million
instructions against 610.4 (-1.9%, the same bits), but the pyramid of 5050
boxes on 1 worker took 1.010 of the time a frame (10 alternating runs
pinned to one core, 0.994 to 1.037) and 0.989 as whole processes (15
pairs, 0.95 to 1.05): not kept. Two workers against one on this host, the same
day, in-process alternating pairs: the pyramid of 9870 boxes 1.78 to 1.88
(5 pairs), the rain of 1e4 1.18 to 1.63 (3 pairs). A caution for any
two-worker figure: with another process busy on the second virtual CPU
the calling thread ran the worker's share itself in 97% of the plain jobs
of the rain of 1e4 (the worker noticed a new job only after the caller had
finished both shares); with the host otherwise idle, in none. Where the
rain of 1e4 loses its second worker (time stamps around the pool's jobs, a
scratch build): over the bench's 70 frames on 2 workers, 359 of 457 million
cycles were inside jobs and 98 million (21%) between them, on the calling
thread alone. Were the jobs 1.7 times as fast on two workers as on one,
that serial part would be 14% of a 1-worker run and two workers would give
1.55x; perfectly shared jobs would give at most 1.75x. The gaps are spread out: after the broad phase's
pair sort up to the body preparation 13.0 million, the greedy colouring
12.5, the rows' packing up to the first substep 10.2, placing the pairs up
to the narrow phase 9.7, the grid's pairs up to their sort 9.4, the sort up
to the movers' pairs 7.6, and the rest under 6 each. The pyramid of 9870
boxes spends 113 of 835 million cycles between jobs on 2 workers, about 8%
of a 1-worker run.

A forty-fifth, on the same host (commits 2822c83 and e98ef61, and a trial
not kept; scratch drivers, not committed). A node steps its world from a
timer, so its workers sleep between frames; every bench here stepped frames
back to back and never saw what that costs. Stepping the pyramid of 9870
boxes one frame every 30 ms, 2 workers took 11.3 to 11.4 ms a frame and 1
worker 11.0 to 11.7: a worker woken from its sleep was queued on the CPU
of the thread that called the step and ran only when that thread paused
(in a test of the pool alone, jobs of 0.2 ms after a sleep, `ps` showed the
worker and the caller on one CPU and the other idle, and the caller ran
every share). Pinned to different CPUs by the driver, the same two threads
took 6.4 to 6.7 ms. Since 2822c83 a woken worker
that finds itself on the caller's CPU narrows its CPU mask to the others,
which moves it at once, and widens it again; the caller yields once after
waking a sleeping worker, so that the worker can run and move before the
shares start: 6.6 to 6.9 ms. The rain of 1e4 on a 16.7 ms clock: the
worker woke on the caller's CPU and moved in 56 to 78% of frames. Back to
back, where the workers stay awake, it changes nothing (6 alternating
rounds, 2 workers over 1, before and after: the pyramid of 9870 boxes 1.66
to 1.74 and 1.64 to 1.75, the rain of 1e4 1.06 to 1.19 and 1.07 to 1.16).
`collision2d_scaling_bench --period-ms` (e98ef61) now measures this;
the pyramid of 9870 boxes, 2 workers over 1 at a 30 ms period, 4
alternating pairs, before 1.26, 1.13, 1.18, 1.25, after 1.71, 1.71, 1.77,
1.77; at 100 ms before 1.15, 1.01, 1.40, 1.40, after 1.21, 1.59, 1.38, 1.79;
the rain of 1e4 at 16.7 ms before 0.82, 0.75, 0.74, 1.04, after 0.87, 0.85,
0.88, 1.24. The rain gains little on 2 workers stepped back to back as
well: in-process alternating pairs today 1.02 to 1.09 (pyramid of 9870
boxes 1.44 to 1.62, rain of 1e5 1.66 and 1.80). This host's two virtual
CPUs also differ in speed: pinned, one worker took 12.1 and 11.9 ms a
frame of the pyramid of 9870 boxes on CPU 0 against 10.2 and 10.2 on CPU
1, and 4.6 against 3.9 ms on the rain of 1e4. Time stamps around the
pool's shares (the rain of 1e4 on 2 workers, frames 62 to 111) found 39 jobs
a frame, 10 of them team jobs, 0.55 to 0.60 ms a frame between jobs and
0.33 to 0.56 ms of the caller waiting for the worker's share, and the
worker's share of a plain job ran longer than the caller's (the narrow
phase 0.50 against 0.29 ms a frame, the movers' boxes 0.39 against 0.26,
publishing 0.15 against 0.07). Tried and not kept: cutting each plain
job's shares in proportion to how fast each worker ran that job's shares
before (a fraction per job, moved a quarter of the way toward the speeds
measured after each run; the same bits): 2 workers took 0.973 of the time
on the pyramid of 9870 boxes and 0.990 on the rain of 1e4 (9 alternating
whole processes each), within the spread.

A forty-sixth, on the same host (trials not kept; the stack trace and
callgrind on the release build). Where the base-60 pyramid's drift comes
from at the defaults: `collision2d_stack_trace --scene stack_pyramid_60
--seconds 60` put the drift since 1 s at 6.38 mm by 5 s and 6.51 mm at 60
s, and the top box's height did not change by 0.1 mm from 5 s on. It is
the end of the pyramid settling into its contacts, which takes longer than
a second, not a creep. The top box rests 232 mm below where it was built
(the column's 61 mm), the sum of each row's compression. That compression
is the soft update's leak: a spring lets go of (1 - mass scale) of its
impulse each pass, so a contact carrying load L holds the gap where its
push-out makes that much back, a gap in proportion to L. Tried and not
kept: letting go only of the impulse above a share b of the one the
contact started the frame with, so that the load carried from frame to
frame does not leak. Over 10 s (drift 1 s -> 10 s, mm; top box below its
built height, mm), the column and the base-60 pyramid: the defaults 0.047,
61 and 6.59, 232; b = 0.25: 0.046, 47 and 7.66, 174; b = 0.5: 0.66, 32
and 35.1, 117; b = 1: the column bounced by up to 44 mm and the pyramid
fell (1.48 m). Each frame's start acts as a slow integrator on the load,
and less compression again made the tall pyramid breathe longer, as the
stiffer contacts of the stack section do. The tiny scenes' time targets:
stepping bullet_wall with 1 substep and 2 passes in fresh worlds of 30
frames, as the paired rounds time them, the soft step ran 4949
instructions a frame and the Fx2D order 3183 (the report's paired rounds
at fcccc0f: 0.361 against 0.183 us). The soft step's extra goes to its
passes over the one manifold that holds the bullet against the wall (662
for the solve and the relax), preparing the bodies (397) and the points
(131), and ordering the manifolds (106). Chipmunk 7, which the target
compares with, lets the bullet through at 0.162 us. Two workers on the
rain of 1e4, back to back, 20 repetitions, alternating whole processes:
2 workers over 1 at 1.39, 1.43, 1.40, 1.41 in one spell (1 worker 3.09 to
3.18 ms a frame) and 1.30, 1.26, 1.38 minutes later, and on a 16.7 ms clock,
interleaved with those, 1.32, 1.23 and 1.11.

A forty-seventh, on a new host of the same kind (scratch changes to the
worker pool and a scratch driver, not committed; `collision2d_scaling_bench
--scene rain --bodies 10000 --workers 2 --reps 20`, whole processes
alternating with the build before, ms a frame). Whether finer shares even
out the two workers: every plain job (not a team's) cut into four shares a
worker, each taken by whichever thread was free, took 2.82, 2.74 and 2.70
against 2.17, 2.15 and 2.17, and with the soft passes' colours cut the
same way 3.42, 3.26 and 3.12. A thread no longer kept to the same items
from job to job, and the stages that stream the points and the bodies
grew (adding the manifolds and preparing their points from 4.1% to 8.0%
of perf's samples over the whole process).
Keeping each worker's own run of four shares first, and taking the
other's only once its own were done, took 2.16, 2.26, 2.19 and 2.13
against 2.24, 2.13, 2.10 and 2.19: no gain, like the balance by measured
speed of the forty-fifth note. One worker on CPU 1 took 2.84 to 3.02 in
the same spell. The same bits across workers, checked wider than the
golden tests: a scratch driver hashed every frame of the elastic gas of
3000 disks, the base-40 and base-100 pyramids, the demo, the column,
the bullet at 1e4 m/s and the heavy box at 1e6, each in the soft step
(defaults; sleeping; exact; 6 substeps, 90 Hz, damping ratio 15 and 2
passes; no kept contacts; time of impact on; no warm start) and in the
Fx2D order (defaults; sleeping), on 1, 2 and 4 workers (the exact mode
not on the base-100 pyramid or the demo, too slow for it): of 122
comparisons with one worker's run, none differed.

A forty-eighth, on the same host (commit 00cd40d; scratch drivers, not
committed). What the time of impact costs a small world when nothing in it
is fast: with `time_of_impact` Auto, each substep's speed check visits
every body (below 16 there is no choosing of candidates, as the
thirty-ninth note explains). Stepping 300 fresh worlds of 30 frames at 1
substep (soft step), whole-process instructions, Auto against Off:
bouncing_disks 53.16 against 50.10 million (49.08 against 46.02 without
building and destroying the worlds, 6.2% fewer, 340 a frame, all in the
check and in the search for a flagged body), incline_slide 66.71 against
65.25 million (2.2% fewer). Off gave the same bits: every body's pose and
velocity at every frame for 60 frames, at 1 and at 4 substeps, on
bouncing_disks, incline_slide, incline, elastic_gas and newtons_cradle.
Alternating whole processes of 20000 such worlds pinned to CPU 1 (11
pairs, medians, Off over Auto): bouncing_disks 0.953 (0.908 to 0.981),
incline_slide 0.966 (0.939 to 0.985). The report's sweep does not vary
`time_of_impact` on these scenes, and the peer its targets miss against,
Chipmunk 7, has no continuous collision: with the time of impact off, the
paired rounds of bouncing_disks in the report at fcccc0f would have come
to about 0.70 of Chipmunk's time (its 0.751 times the instruction ratio,
an estimate, not a timed round) and incline_slide to about 0.76. A user
whose bodies never cross half their thinnest width in a substep can turn
it off for that; the soft step also stopped the bullets of the report at
500 and 1e4 m/s with it off (its contacts are found within the frame's
reach), but a body knocked fast during the frame is not covered then.
The tiny scenes' time targets sit inside what code layout does to them.
The same source built five ways (the default, and with
`-falign-functions=32` or `64` or `-falign-loops=32` or `64`; scratch
builds of the sweep bench), each timed twice by the report's paired rounds
(7 rounds, CPU 1), ours over Chipmunk 7: bouncing_disks (ours soft step
1x2 against its defaults) 0.721 to 0.804, ours 0.306 to 0.338 us a frame
(the default build 0.756 and 0.747); incline_slide (1x2 against 1x8) 0.780
to 0.835; bullet_wall (Fx2D 1x2 against 1x8) 1.069 to 1.168. Chipmunk, a
shared library, kept its times (0.416 to 0.431, 0.706 to 0.719 and 0.159
to 0.161 us). So bouncing_disks meets or misses its 0.75x by where the
linker puts our code, while incline_slide and bullet_wall miss in every
layout. Three changes to the Auto check showed the same: the check in a
pass of its own with no branch a body (1.0% fewer instructions on
bouncing_disks, 0.2% more on incline_slide) took 0.97 and 1.01 of the time
in whole processes; the same pass with a branch a body 1.11 and 0.98; one
`&&` made `&` in the shipped loop 1.04 and 0.96. None is kept: on frames
this small a change is judged by its instructions, and none saved enough.
The report run right after, on the same core code, timed bouncing_disks at
0.806 and incline at 0.774 (0.73 in the report before): the host's spells
add to the layout's spread.

A forty-ninth, on the same host (commit ffeb066; the scaling bench, and
trials not kept). What a core another process keeps busy does to two
workers: with `taskset -c 0 sh -c 'while :; do :; done'` running, 5 rounds
of `collision2d_scaling_bench --workers 2` for the build before and after,
and 1 worker pinned to CPU 1, ms a frame. Before, the soft passes, the
rows' placing and the manifolds' ordering were team jobs whose members all
met after each colour; a worker waiting behind the busy loop stalled every
meeting. Two workers then took 1.77 times one worker's time on the pyramid
of 9870 boxes (median of the rounds' ratios; 1.42 to 2.10), 1.80 on the
rain of 1e4 (0.94 to 4.57) and 1.37 on the rain of 1e5 (1.31 to 1.58).
Since ffeb066 those jobs run in stages whose untaken shares any thread may
run: 1.10 (1.06 to 1.15), 1.05 (0.92 to 1.20) and 1.03 (1.01 to 1.22).
Box2D v3 in the same rounds, 2 workers over 1: 0.95, 1.01 and 0.90. On an
idle host the staged jobs cost nothing measurable (alternating runs, after
over before: pyramid of 9870 1.005, rain of 1e4 1.003, rain of 1e5 1.01,
the base-100 pyramid on 1 worker 1.0), and every body's pose and velocity
over 90 frames hashed the same before and after, on 1, 2 and 4 workers and
with the busy loop. The change moved what the link-time inliner kept
inline elsewhere: in a two-body frame three of the point verbs' innermost
steps became calls (+3.9% instructions on incline_slide); since 017e7d4
they are always inlined, and 100 fresh worlds of 30 frames at 1 substep
ran +1.4% on incline_slide, +1.2% on bouncing_disks and +0.1% on
bullet_wall (Fx2D) against 0862752. Not kept: four shares a worker in each stage, taken the
same way, cost 2 to 8% on an idle host (a thread that finishes first takes
the other's last share and, with it, bodies that sit in the other core's
cache) and gained nothing with the busy loop; and the soft passes' file
built for AVX-512 (32 vector registers instead of 16, the same four lanes)
took 1.37 times as long on the base-100 pyramid.

A fiftieth, on the same host (commit f240943; scratch drivers forcing a
lane path, whole processes timed in alternating pairs). The forty-ninth's
AVX-512 trial kept four lanes a vector and only gained registers; the
eight-lane path solves two neighbouring batches of one colour in one
512-bit vector, which a colour allows (its batches share no body), so the
bits stay those of every other path. As first written it ran about 1.2 times the
four-lane path's time on the base-100 pyramid: `rows::apply` was left out of
line, every field's second address was worked out from two pointers, and
each field was loaded by two masked broadcasts. Inlined, with the second
batch a constant stride on, and loaded by one load and one insert, its
solve of eight manifolds is 1087 instructions (148 touching the stack)
against 764 (218) for four on the four-lane path. Eight over four lanes,
the base-100 pyramid stepped 60 + 150 frames on 1 worker: 0.835 (9 pairs,
0.81 to 0.86), the top box's height the same to the bit; the pyramid of
9870 boxes, 60 frames with set-up: 0.878 on 1 worker (7 pairs) and 0.92
on 2. Outside the eight-lane rows no function of the optimised benchmarks
holds an AVX-512 instruction (their disassembly), so the run-time choice
guards them as it does the four-lane rows.

A fifty-first, on the same host (commit cfb4ef9; the scaling bench, and a
scratch driver timing each stage of a frame). The rain of 1e5 bodies on 1
worker took 64 ms in its frame 72 against 14 ms in the frames around it:
the broad phase took 54 ms of it. The kept pairs (fat_box_pairs.h) had
waited 32 frames since boxes last left their enlarged ones and tried again:
the falling bodies' enlarged boxes made 393749 pairs against 25380 exact
ones, and the next frame's boxes had left them. Since cfb4ef9 a try only
enlarges the boxes and pairs the exact ones; the enlarged boxes are paired
at the first frame in which every box stayed inside them. The pairs are
the same, and so are the bits (every body's pose and velocity over 90
frames of that rain on 2 workers hashed alike before and after). The
scaling bench's own figure, after over before, 7 alternating runs: the
rain of 1e5 0.756 on 1 worker (0.72 to 0.77) and 0.718 on 2 (0.69 to
0.76), the try falling in the timed frames; whole processes 0.978 and
0.963. The rain of 1e4 tries in its frame 72 too (5 to 7 ms before, 1.2
ms after, of frames of 1.2 to 1.8 ms), but the bench's median of five
repetitions leaves that repetition out: 1.03 (0.98 to 1.15, 11 runs), and
whole processes 0.986 (1 worker) and 0.994 (2). The pyramid of 9870 boxes,
which rests, reuses its pairs one frame later: whole processes 0.999.
Not kept: the manifolds' colours written apart from the notes, so that
colouring (one thread) writes no line the workers wrote at prepare. On 2
workers the pyramid of 9870 boxes coloured in 0.19 ms instead of 0.25, but
the workers' next prepare took 1.37 ms instead of 0.68 (a frame 6.8 ms
instead of 6.2). A sequential write over the notes before the colouring
gave the faster prepare back: the prepare's time depends on which core
last wrote the notes, and the separate colours gained nothing overall.
"""
