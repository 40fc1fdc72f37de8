//! Mechanisms from joints and links: the peers' formats read, solved and
//! held to the peers' own numbers.

/// pyslvs's example mechanisms against pyslvs.
mod pyslvs;

/// pylinkage's example linkages against pylinkage.
mod pylinkage;
