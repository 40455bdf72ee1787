//! Builders shared by concurrent evaluations: each evaluation borrows one (keeping its last
//! build, so geometry-preserving candidates re-use it) and returns it.

use std::sync::Mutex;

use super::builder::ModelBuilder;

/// A pool of model builders, one per concurrent evaluation.
#[derive(Default)]
pub struct BuilderPool {
    builders: Mutex<Vec<ModelBuilder>>,
}

impl BuilderPool {
    /// Runs `f` with a pooled builder, or with `make()` when none is free.
    pub fn with<R>(&self, make: impl FnOnce() -> ModelBuilder, f: impl FnOnce(&mut ModelBuilder) -> R) -> R {
        let mut builder = self.builders.lock().expect("builder pool").pop().unwrap_or_else(make);
        let result = f(&mut builder);
        self.builders.lock().expect("builder pool").push(builder);
        result
    }

    /// Model builds so far across all builders.
    pub fn rebuild_count(&self) -> usize {
        self.builders.lock().expect("builder pool").iter().map(|b| b.rebuild_count()).sum()
    }
}
