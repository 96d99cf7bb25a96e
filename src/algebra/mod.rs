//! Number types beyond the rationals: exact real algebraic numbers.

pub mod real_algebraic;
