//! What a voxelization run did ([`Work`]), what it hands its slices to ([`SliceSink`]) and
//! the process's own memory in every estimate ([`PROCESS_BYTES`]): shared by both drivers,
//! the slab routes (`drive`) and the run route (`runs`). A leaf module, so that `drive`, which
//! dispatches to `runs`, is not needed back by it.

use crate::slice::OpCounts;
#[cfg(doc)]
use crate::slicer::Route;

/// What a run did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Work {
    /// Voxels inside the scene.
    pub filled: usize,
    /// Array clocks for every P·Vz frame (simulated on the array route, counted from the
    /// programs on the others: the same number either way).
    pub cycles: u64,
    /// P·Vz frames drawn (primitives × slabs).
    pub frames: u64,
    /// The evaluator's operations (§5.5): per voxel (the stack: per slice) on the slab
    /// routes, per segment of a column on [`Route::Runs`].
    pub ops: OpCounts,
    /// Pixel-clocks the simulator ran (array route: Σ over simulated frames of pixels ×
    /// clocks; 0 on the other routes, which simulate no pixel).
    pub simulated_pixel_clocks: u64,
    /// Pixel-clocks of every frame on the whole array: what simulating everything costs.
    pub full_pixel_clocks: u64,
}

/// The process before any voxel: code, libraries, the scene.
pub const PROCESS_BYTES: u64 = 16 << 20;

/// Receives slice k's colour codes ([`crate::voxelize_streaming`]); an error (of the sink's own
/// type `E`) stops the run.
pub type SliceSink<'a, E = crate::Error> = dyn FnMut(usize, &[u8]) -> Result<(), E> + 'a;
