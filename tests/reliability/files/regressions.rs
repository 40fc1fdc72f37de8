//! What the campaigns over mechanism texts and files found, each kept as
//! the smallest text that shows it.
