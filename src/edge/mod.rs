//! Edge functions (Pineda 1988): `E(p) = (p.x - a.x)(b.y - a.y) - (p.y - a.y)(b.x - a.x)`
//! in exact ([`exact`]), fixed-point ([`fixed`]) and float ([`float`]) forms.
//!
//! Every form orients a triangle so that its interior is `E > 0` on all three edges and
//! derives each edge's inclusive flag with [`crate::convention::TieRule::is_inclusive`].

pub mod exact;
pub mod fixed;
pub mod float;
