"""The profile notes from the fifty-second on. report_profile_notes.py joins
them to the earlier ones."""

PROFILE_NOTES_LATEST = """A fifty-second, on the same host (commit f3295f8; callgrind, the stack
bench, and scratch drivers with a timer around each stage of a frame, not
committed). This host ran in two speeds during these measurements: one
binary took 4.5 or 6.5 ms a frame from one process to the next. The figures
below are therefore instruction counts, or ratios within one process whose
engines take turns.

In its first second (the stack bench's timed second) the base-100 pyramid
sinks about 0.1 m as its contacts take the load, and a box left its
enlarged box (fat_box_pairs.h, 0.1 m) nine times in 60 frames. Each time
the broad phase paired the exact boxes, waited a frame, paired them again
while enlarging, and paired the enlarged boxes the frame after. Since
f3295f8, where the last enlarged boxes served at least two frames and paired
at most twice as many boxes as the exact ones, new enlarged boxes are made
and paired at once and give that frame's pairs (base-100: 16740 enlarged
pairs against 14950 exact ones). A rain keeps the cautious path: in 150
frames of the rain of 1e4 and of 1e5 it never made them again at once.
Same pairs, same bits. Callgrind, the first 60 frames: the step 3749 ->
3690 million instructions (-1.6%), the broad phase 155 -> 83 million. The
stack bench, base-100 pyramid, ours over Box2D v3 (median of 7 rounds in
one process), 5 processes each: 1.29, 1.28, 1.30, 1.32, 1.33 before; 1.24,
1.26, 1.23, 1.23, 1.25 after. The base-60 pyramid, whose boxes left their
enlarged boxes twice in 60 frames: 1.32 to 1.37 before and after.

Where the rest of the base-100 frame goes, beside Box2D v3's own profile
(`b2World_GetProfile`): one process built each engine's pyramid afresh and
stepped it 60 frames, the engines in turn, 7 rounds (ours 1.28x, medians,
ms a frame, the host in its slower speed). Finding the contacts: ours 1.05
(broad phase 0.28, poses 0.14, narrow phase 0.63), Box2D v3 2.27 (pairs
0.98, collide 1.13, refit 0.16). Building the solver's data: ours 2.52
(adding and preparing the points 1.24, the bodies 0.16, their rows 0.07,
ordering and colouring 0.30, filling the rows 0.74), Box2D v3 0.34 (its
prepare; it colours a contact when it starts touching). The passes: ours
2.69 (solve 1.67 with its warm start, relax 1.02), Box2D v3 2.62 (warm
start 0.47, solve 0.85, relax 1.30). The body passes: 0.43 and 0.45.
Publishing the contacts: ours 0.81, Box2D v3 0.15 (it stores the impulses
in its contacts). So the frame's extra 1.7 ms are the data built and
published per frame (2.9 ms more than Box2D v3), less the cheaper finding
(kept manifolds and pairs). To reach 1.0x, building and publishing must fall
from about 3.3 ms to about 1.6 ms at that host speed: a contact record that
persists between frames and that the rows are filled from and write back to.

Tried, not kept. A contact point 64 bytes larger (320 instead of 256): the
base-100 frame moved within the host's spread (4.15 to 4.65 ms against 4.25
to 4.70). A published contact 40 bytes larger: likewise. So the stages
above are not paying for the records' size. A pair's bodies and materials
read once for both its points at prepare: 547.56 million instructions
before and after (8 frames). The manifolds' height order, which the
colouring follows, never repeated between frames (0 of 299 frames, base-100
and the pyramid of 9870 boxes): equal heights in a row jitter, so colours
can be kept between frames only if kept as state, which a snapshot would
then have to carry to resume exactly.

A fifty-third, on the same host (commit 66876c6; the stack bench,
callgrind and scratch changes, none kept). On the base-100 frame the bytes
a stage touches cost more than its instructions suggest. A 64-byte block
added to each contact point, written when the point is added and read when
its row is filled and when it is published, raised the instructions of the
first 60 frames by 0.68% (3686.6 -> 3711.7 million) but the time over
Box2D v3 from 1.23, 1.24, 1.26, 1.23 and 1.26 to 1.33, 1.29, 1.33, 1.32
and 1.31 (stack bench, median of 7 rounds in one process, 5 alternating
processes each). One more cache line a point in three stages cost about
6%. The larger point of the fifty-second changed nothing because no stage
touched its extra bytes. The point's 256 bytes are four lines: filling the
rows reads three of them and publishing three. Filling needs about 170
bytes and publishing about 130, 223 together, so no order of the fields
lets either read fewer lines; only fewer bytes a point would.

Tried and not kept:
- A pass after the substeps copying each row point's impulses and sliding
  flag into a 24-byte record in point order, so that publishing reads them
  in order instead of gathering each point's row: 1.30 to 1.36 against
  1.24 to 1.30 before (5 alternating processes each). The extra pass
  brings the rows through the cache again.
- A kept manifold's points worked out where they are added, from its
  cached contacts, instead of written into the pair's manifold (104 bytes)
  by the narrow phase and read back: 1.28 to 1.32 against 1.18 to 1.27.
  Turning the lever arms a second time added 2.3% of the instructions
  (3772.3 million), more than the bytes saved.
- Each row's two spring fields (16 of a lane's 256 bytes) left out, each
  pass choosing the lane's spring from the frame's two by its masses, as
  `ContactSprings::of` does: the same bits, rows 6% smaller, and 1.22 to
  1.31 against 1.22 to 1.25 before (pinned to one core while a fuzzer
  ran on the other). The passes, which Box2D v3's match in
  time, did not speed up with fewer bytes; the choice is work in every pass.

So the persistent contact record must bring fewer bytes through the
stages that build and publish the points without adding work, not only
move the same bytes around.

The tiny scenes: a fresh incline world (1 substep, sleeping on), stepped
30 frames as the paired rounds time it. Its first frame ran 18.2 thousand
instructions, frames 2 to 30 about 6.4 thousand each, and once the box
sleeps (from about frame 31) 0.34 thousand. The 6.4 thousand are spread
over the frame's stages: the largest share, detection's own code, is 675
and the one manifold's solve 583. Sizing the soft step's eleven per-body
arrays only when the body count changes took 85 instructions off a frame
(1.3%). That was not kept: the three scenes' time targets miss by 4 to 5%.

Disks on turning kinematic faces (this host, scratch drivers linked to the
release build, not committed). A frame's contact keeps its normal and its
point on the face from prepare; on a kinematic bar 2 m long turning about
its middle, a disk of 1 cm radius sliding out along it sank 0.455, 3.41
and 6.71 mm at 1, 3 and 5 rad/s (4 substeps of 1/60 s, frictionless) and
went through from 15 to 20 rad/s. Three ways to follow the face each pass,
on that bar at 5 rad/s and on a 0.5 m box sliding off a 6 m platform
tilting at 0.5 rad/s (friction 0.5; the box's deepest corner, mm): the
frame's normal and lever arms with only the gap measured on the turned
face, 6.19 and 0.110; the normal and the arms turned to the pass, 1.83 and
0.331; the same solved for the middle of the next move (normal turned on by
half a substep, the face's arm to where the disk's point will be then),
0.112 and 0.971. At 64 substeps the last gave the box 0.088 mm, so its
error falls with the substep, but at 4 it pitched the sliding box forward
by 0.0018 rad against the platform, which the frame's contact did not (the
box then rode up to 0.79 mm off the face instead). Without friction the box
sank 0.16 mm followed and 0.20 mm on the frame's normal and arms. So only
a disk follows the face,
and its point is its nearest one, turned with the face, not a point of
its rim, which a rolling disk turns away: frictionless, 0.0010, 0.010,
0.030, 0.13 and 0.55 mm at 1, 3, 5, 10 and 20 rad/s; with friction 0.5,
0.032, 0.24, 0.57, 1.25 and 2.4 mm, and at 64 substeps 0.0023 to 0.21 mm
(the error with friction falls with the substep too; where it comes from
is not found). Worlds without a turning kinematic polygon pay two compares
a pass (callgrind, 600 frames at 4 substeps: incline 8.668 -> 8.692
million instructions, bouncing_disks 7.883 -> 7.908, heavy_on_light_1e2
13.445 -> 13.469, elastic_gas 1026.96 -> 1027.00, about 40 instructions a
frame). A first version that asked each body at prepare whether it was a
turning kinematic one cost 70 a frame; the body census, counted at each
edit, now says so.

Fast kinematic faces that strike bodies (this host, scratch drivers linked
to the release build, not committed). A 2 cm paddle 2 m tall moving along
x at a disk of 1 cm radius 0.5 m away, no gravity, 60 frames at the
defaults; a run fails when the disk is ever more than 1.1 mm behind the
face at a frame end (the Fx2D order lets contacts overlap by its 1 mm
slop). In the Fx2D order, which finds contacts where a substep ends, the paddle
passed a single disk at 2567 of 3600 speeds from 4 to 40 m/s (head on;
2504 with the face turned 0.3 rad) and at 2888 of 2891 from 40 to 4000
m/s; sweeping the fast paddle and pushing the struck disk ahead of it from
the time of impact, 0 of them, the disk at most 4.7e-13 m behind the face.
The soft step keeps the single disk ahead at any speed, but a disk it
drives into a second one stops at their time of impact (the frame found
no contact between the two) and was held there for the rest of the frame
while the face ran on. A row of two disks 5 cm apart, the second 3 mm off
the line, 30 frames; runs whose disk ended behind the face, old -> new, at
speeds 1 to 10 m/s (301 runs), 10 to 50 (308) and 50 to 200 (301): soft
step 78 -> 0, 263 -> 0, 301 -> 0 (runs with a disk more than 2 mm behind
the face at any frame end: 118 -> 0, 280 -> 0, 301 -> 0); Fx2D 111 -> 5,
285 -> 116, 288 -> 71. A row of three disks 3 cm apart: soft step 0 -> 0,
186 -> 9, 285 -> 1 (more than 2 mm behind at a frame end: 96 -> 96, 299 ->
132, 300 -> 44; the 96 at 1 to 10 m/s are the soft contacts squeezing
three disks, where the paddle is too slow to be swept); Fx2D 149 -> 117,
296 -> 191, 288 -> 210. What is left in the Fx2D order is a pushed body
that a push moves sideways off the one pushing it (the gap that opens
leaves it no contact, so no velocity) and that the face then overtakes,
and the Fx2D position passes squeezing three disks against the face (at 6
m/s one was pushed 13 mm back through it with no push involved). A
kinematic body takes the dynamic bodies' sweep threshold, and the books
of pushes are kept only in worlds whose body census counts a moving
kinematic body; the grown boxes of stopped bodies run only in Fx2D frames
with a stop: callgrind, 600 frames, instructions before -> after, soft step
4 substeps: incline 8.692 -> 8.677 million, bouncing_disks 7.908 -> 7.895,
heavy_on_light_1e2 13.469 -> 13.456, elastic_gas (300 frames) 514.9 ->
513.2; Fx2D 1 substep: bullet_wall 3.571 -> 3.570, newtons_cradle 4.038 ->
4.034. A first version that checked each body for a push where it moves
and holds cost bouncing_disks 4.9%, as the move pass then no longer
inlined into the step; one that asked each body at prepare whether it was
a fast kinematic one cost elastic_gas 0.6% the same way.

Spinning kinematic faces that strike bodies (this host, scratch drivers
linked to the release build, not committed). A kinematic bar 2 cm thick
turning about its middle at a constant spin, no gravity, defaults; a disk
of 1 cm radius, or a box 2 cm square (square to the world's axes, or
turned 0.4 rad), at rest 0.5 rad ahead of the bar; a run passes through
when the bar turns 0.3 rad past the body without having given it any
velocity. Runs that passed through, before (5600d57) -> after, Fx2D order:
a 1 m bar, the body 0.4 m out, 80 spins from 1 to 2000 rad/s (each 1.1
times the last): disk 40 -> 0, box 38 -> 0, turned box 40 -> 0 (the disk's
first at 17.4 rad/s, a point speed of 7.0 m/s); a 2 m bar, the body 0.9 m out,
207 spins from 1 to 60 rad/s (each 1.02 times the last): disk 74 -> 0,
box 68 -> 0, turned box 74 -> 0. The bar of the turning-face test (2 m,
the disk resting 0.8 m out): spins of 10 to 30 rad/s in steps of 1, 7 of
21 -> 0; at 5 rad/s the frictionless disk left the tip at 5.753 -> 5.734
m/s. The soft step, whose frame contact holds such a pair, changes only
where the frame found none: runs of the first scan that passed through,
disk 1 -> 1, boxes 2 -> 2 (after: the disk at 1539 rad/s, the boxes at
718 and 1399, turns of 3.0 to 6.4 rad a substep); runs with the disk more than 5 mm into the bar, 1 m bar 7
-> 5 of 80, 2 m bar 22 -> 22 of 207 (from a point speed of about 35 m/s,
the soft contact's compliance). Three versions did worse before the one
kept. Pushing a struck body along the first contact normal let a face
turning 1.15 rad in a substep (277 rad/s) leave the disk behind it, the
push along a tangent falling short of the arc. Carrying every body that
the turning sweep stopped round with the face glued a disk resting on it
in place (at 5 rad/s it reached 155 m/s without sliding out), because a
straight move falls behind a turning face however slowly it turns, so
every such body was stopped. Lifting a body back to the height it touched
at, gap included, left it a few nanometres clear, outside detection's
touch tolerance, so the velocity stage never saw it (it left at 4.0 m/s,
the speed of its first strike). Only worlds whose census counts a
spinning kinematic polygon take the new paths; callgrind, 600 frames,
instructions before -> after: soft step 4 substeps incline 8.677 -> 8.682
million, bouncing_disks 7.895 -> 7.900, heavy_on_light_1e2 13.456 ->
13.461, elastic_gas (300 frames) 513.17 -> 513.17; Fx2D 1 substep
bullet_wall 3.570 -> 3.572, newtons_cradle 4.034 -> 4.036.

Spinning dynamic polygons that strike bodies (this host, scratch drivers
linked to the release build, not committed). A dynamic rod 2 cm thick and
1 kg, at rest at the origin and spinning at a set rate, no gravity,
defaults; a disk of 1 cm radius and 10 g (or static) at rest ahead of it;
a run passes through when the rod's angle goes 0.3 rad past the disk's
with neither body having moved. Runs that passed through, before
(0096664) -> after: a 1 m rod, the disk 0.4 m out and 0.5, 1 or 2 rad
ahead, 80 spins from 1 to 2000 rad/s (each 1.1 times the last): Fx2D
order 40, 42, 44 -> 0, 0, 0 (the first at 17.4 rad/s, a tip speed of 8.7
m/s); soft step 0, 37, 32 -> 0, 0, 0 (from 60 rad/s at 1 rad ahead). A 2 m
rod, the disk 0.9 m out, 207 spins from 1 to 60 rad/s (each 1.02 times
the last): Fx2D 74, 75, 68 -> 0, 0, 0; soft step 0, 0, 1 -> 0, 0, 0. With
the disk static, 0 of 80 after in both pipelines at 0.5 and 2 rad ahead.
The soft step's passes were pairs its frame contact held: the rod turned
past what the contact, its normal and point fixed at prepare, could
follow. Sweeping the rod turning but leaving such pairs to the contact
kept 37 and 32 of them; they are swept now when either body is swept
turning. Without stopping the turn where the sweep stops the body, the
test's disk went 20 mm deep (the soft step at 30 rad/s) and the Fx2D order
passed through from 100 rad/s. The spin floor (the thinnest half-width's
share of the reach over the widest dynamic polygon's bounding radius, 170
rad/s for the unit boxes of a pyramid at 4 substeps) spares the exact test
per body; worlds without a dynamic polygon skip it. Cost, callgrind, the
tiny-scene driver (600 frames, 300 for elastic_gas and the pyramid),
instructions 0096664 -> 3ad9aee: soft step 4 substeps incline 8.675 ->
8.755 million (+0.93%), bouncing_disks 7.894 -> 8.032 (+1.76%),
heavy_on_light_1e2 13.453 -> 13.530 (+0.57%), elastic_gas 513.29 ->
518.03 (+0.92%), base-20 pyramid 735.0 -> 739.2 (+0.57%); Fx2D 1 substep
bullet_wall 3.556 -> 3.573 (+0.46%), newtons_cradle 4.023 -> 4.061
(+0.95%), Fx2D 4 substeps base-20 pyramid 4020.7 -> 4022.6 (+0.05%). The
added work is each body's spin test in every substep's marking and each
free body's at prepare (Box2D v3 tests each body's angular reach in the
same way). Two cheaper forms did worse: a per-frame threshold array made
the prepare's check too large to inline (elastic_gas +2.1%), and a
separate loop for worlds whose spins need no check shifted inlining so
incline and bouncing_disks rose 1.8% and 2.0%. Whole processes of the
stack bench on the base-100 pyramid (3 s simulated, 7 pairs pinned to CPU
1), after over before: 1.0125 wall (0.966 to 1.061). A plank 10 cm thick
thrown at 5 m/s from 2 m onto a rough ground, spinning at 50, 200 or 1000
rad/s (1 m and 3 m long, 1200 frames): none went through the ground before
or after; the deepest corner while over the ground, before -> after, Fx2D
3.98 -> 1.15 mm (1 m, 50 rad/s), 2.61 -> 1.11 mm (1 m, 200 rad/s), 1.21 mm
-> no overlap (3 m, 200 rad/s); soft step 31.0 -> 0.36 mm (1 m, 200 rad/s)
and 11.4 -> 0.000015 mm (3 m, 200 and 1000 rad/s, the soft step's turn cap
making them one run); the other runs alike or unchanged.

Reading a polygon's bounding radius from the body, which the test does
only above the spin floor, instead of keeping it in an array of its own
saves 8 bytes a body and gave, 0096664 -> the commit that dropped the
array: incline +0.92%, bouncing_disks +1.56%, heavy_on_light_1e2 +0.50%,
elastic_gas +0.92%, base-20 pyramid +0.53% (soft step); bullet_wall
+0.43%, newtons_cradle +0.84%, base-20 pyramid +0.04% (Fx2D); the scans
and the planks print the same.

Small worlds' frames, and what the report's short runs weigh (a scratch
driver stepping fresh worlds of the bench scenes, callgrind on the release
build; steady frames from 300-frame runs less 30-frame runs). A small
world's frame is mostly fixed work: body passes, the broad phase, the
report. Sizing the soft step's body arrays only when the body count
changes, summing a world of one energy block without the block list, and
touching the contacts' pages only when their list grows took, in
instructions a steady frame, bouncing_disks at 1 substep 6104.7 -> 5891.2
(-3.5%), incline_slide at 1 substep 5121.5 -> 4867.5 (-5.0%),
bouncing_disks at 4 substeps 10430.9 -> 10217.2 (-2.0%), the base-20
pyramid 2448842 -> 2448623, with the same bits. The time target's runs
are 30 frames from a fresh world, and a fresh world's first frame costs 3
to 4 times a steady one: it sizes some 35 buffers (34 allocations on
bouncing_disks, 37 on the inclines) and builds the resting grid and the
body census. Timed apart (2000 fresh worlds, medians, pinned to one core,
before the change above): first frame 1.39 us against 0.35 us for the
30th on bouncing_disks, 1.51 against 0.50 us on incline, 1.53 against
0.57 us on incline_slide, so 5 to 9% of such a run is the first frame's
extra. Taking those buffers from one block would shorten it; they are
kept between frames, so that is left for a change of the body arrays'
layout.

The static crossing sweep's cost, and why its move test rides in the last
substep's move pass (callgrind on the release build, same driver;
instructions a steady frame, 7b2795b -> f47a60e -> f24b893):
bouncing_disks at 1 substep 5878.2 -> 6030.0 -> 6034.8, incline_slide
at 1 substep 4890.5 -> 5031.3 -> 5038.7, bouncing_disks at 4 substeps
10204.2 -> 10486.0 -> 10526.2, the base-20 pyramid 2448821 -> 2464675 ->
2454630; bullet_wall in the Fx2D order at 1x2 2752.0 -> 2814.0. The
small scenes pay for the sweeps their fast bodies need (incline_slide's
box is swept in about one frame in five). At f47a60e the pyramid paid
0.65% for a test it never passes: the compiler had stopped inlining the
move pass's per-body function. A separate pass for the test, inlined,
cost the pyramid 0.23% and the small scenes 3.7 to 4.2%; the test inside
the last move pass, inlined, costs 0.24% and 2.7 to 3.1%.

Round contacts in the soft step (commits 6e22b58, 0515ddc and f372024;
scratch drivers and callgrind on the release build, not committed). A
frame's contact follows its bodies from lever arms rotated with them, and
a rotated disk arm lifts off the surface by r (1 - cos turn), which is why
a touching body's spin was capped at a quarter turn a substep. A disk's arm
now moves along its surface by the arc it rolls, and the cap is for
polygons only. A disk rolling on a rough ground for 2 s, speed kept,
d59435c -> now: 1 cm at 2 m/s 0.228 -> 0.995 (1 substep), 0.661 -> 0.999
(4 substeps); 5 cm at 10 m/s 0.231 -> 0.999 and 0.797 -> 1.000. A plank
(6 m x 0.1 m, 1 kg) sliding without friction over static pegs of 0.1 m
radius 0.5 m apart, its bottom level with their tops, rose 317 mm at 6 m/s
and 4 substeps: the corner arriving at a peg held a contact found 41 mm
away, whose normal was tilted 45 degrees, and the solver pushed along it
each substep. One-point disk-disk and vertex-disk contacts that cannot
bounce and whose centres slide more than 1% of their distance a frame now
follow the line between the centres, their distance less the radii, and a
speculative gap only as far as their path closes before they touch. Highest
rise / speed kept at the end, before -> after: 4 substeps, 2 m/s 7.12 mm /
0.45 -> 0.084 mm / 0.98; 6 m/s 317 mm / 0.30 -> 1.76 mm / 0.95; 1
substep, 6 m/s 256 mm / 0.20 -> 24.7 mm / 0.56 (the Fx2D order 15.2 mm,
Box2D v3 0.1 mm at 6 m/s and 8.2 to 13.5 mm at 2 m/s). The rise that is
left at one substep is the plank sagging about a millimetre into the pegs
it rests on, so that a corner strikes the next one. On kinematic rollers
spinning at 60 rad/s (4 substeps) the plank sank 6.5 mm and was then thrown
up to 57 mm; now it stays within -0.05 .. +0.9 mm of rest. Instructions a
steady frame, d59435c -> f372024: bouncing_disks (1 substep) 6036.1 ->
6061.6, incline_slide 5048.2 -> 5077.9, bouncing_disks (4 substeps)
10527.6 -> 10572.3, the base-20 pyramid 2454629 -> 2460558 (+0.24%: the
disk test in the move pass), elastic_gas 1806830 -> 1795131,
newtons_cradle 14982 -> 14950. The per-frame census skips the scan for
such points in worlds whose bodies all bounce. The scaling bench's rain of
20000 bodies ran 2225.3 -> 2214.9 million instructions: the static crossing
pass had gone out of line with its lambda when the soft frame grew (2252.4
million), and is inlined by request since 6e22b58.
"""
