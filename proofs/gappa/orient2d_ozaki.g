#@-Eprecision=200
# Gappa proof of the orient2d filter of certimesh: Ozaki, Buenger, Ogita, Oishi and Rump's
# filter shape (BIT 56, 2016). Models orient2d_filter in
# predicates/include/certimesh/predicates/detail/filters.h operation by operation:
#   dl = fl(fl(a.x - c.x) * fl(b.y - c.y)),  dr = fl(fl(a.y - c.y) * fl(b.x - c.x)),
#   det = fl(dl - dr),  s = fl(dl + dr),
#   bound = fl(fl(theta * |s|) + underflow_bound),  certain when |det| > bound.
# Binary64 round-to-nearest, no FMA. Written by hand (not by generate.py); derivation and
# the cases this script does not cover (dl and dr of opposite signs; the mirrored signs)
# in proofs/README.md, section 10. Checked by the CTest tests proofs.gappa.orient2d_ozaki,
# proofs.coq.orient2d_ozaki and proofs.constants_match.
#
# Case proved here: dl >= 0 and dr >= 0 (as computed). Then the certification det >= bound
# implies that the exact determinant Det = (a.x - c.x)(b.y - c.y) - (a.y - c.y)(b.x - c.x)
# is positive. No normalization: dl and dr range over all finite non-negative doubles,
# products carry the absolute underflow error eta, sums and differences none (section 2).
# The exact products are recovered from the rounded ones:
#   dl = fl(acx * bcy) = acx * bcy * (1 + d_dl) + eta_dl,  acx = (a.x - c.x)(1 + d_acx), ...
# so (a.x - c.x)(b.y - c.y) = (dl - eta_dl) / ((1 + d_acx)(1 + d_bcy)(1 + d_dl)).
# -Eprecision=200: theta's margin over the first-order 3u is about u^2, below Gappa's
# default interval precision.
#
# @predicate orient2d_ozaki
# @theta 0x1.8000000000005p-52
# @underflow_bound 0x1p-1073

q_dl = (1 + d_acx) * (1 + d_bcy) * (1 + d_dl);
q_dr = (1 + d_acy) * (1 + d_bcx) * (1 + d_dr);
DL = (dl - eta_dl) / q_dl;   # exact (a.x - c.x)(b.y - c.y)
DR = (dr - eta_dr) / q_dr;   # exact (a.y - c.y)(b.x - c.x)
Det = DL - DR;
det = (dl - dr) * (1 + d_det);
s = (dl + dr) * (1 + d_s);
t = 0x1.8000000000005p-52 * s * (1 + d_t) + eta_t;
bound = (t + 0x1p-1073) * (1 + d_bound);
k = (1 + d_s) * (1 + d_t) * (1 + d_bound) / (1 + d_det);

{
     dl in [0, 0x1p1024]
  /\ dr in [0, 0x1p1024]
  /\ |d_acx| <= 0x1p-53
  /\ |d_bcy| <= 0x1p-53
  /\ |d_dl| <= 0x1p-53
  /\ |eta_dl| <= 0x1p-1075
  /\ |d_acy| <= 0x1p-53
  /\ |d_bcx| <= 0x1p-53
  /\ |d_dr| <= 0x1p-53
  /\ |eta_dr| <= 0x1p-1075
  /\ |d_det| <= 0x1p-53
  /\ |d_s| <= 0x1p-53
  /\ |d_t| <= 0x1p-53
  /\ |eta_t| <= 0x1p-1075
  /\ |d_bound| <= 0x1p-53
  /\ det - bound >= 0
  -> Det >= 0x1p-1077
}

# Det = (det - bound) / (1 + d_det)                        [>= 0 by the certification]
#     + dl * (theta k - (1 - 1/q_dl)) + dr * (theta k + (1 - 1/q_dr))
#                                                        [>= 0: theta k covers 3 roundings]
#     + ((eta_t + underflow_bound)(1 + d_bound)/(1 + d_det) - eta_dl/q_dl + eta_dr/q_dr)
#                                                        [> 0: underflow_bound covers the etas]
Det -> (det - bound) / (1 + d_det)
     + (dl * (0x1.8000000000005p-52 * k - (1 - 1 / q_dl))
        + dr * (0x1.8000000000005p-52 * k + (1 - 1 / q_dr)))
     + ((eta_t + 0x1p-1073) * (1 + d_bound) / (1 + d_det) - eta_dl / q_dl + eta_dr / q_dr);
