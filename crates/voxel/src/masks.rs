//! Slab masks from the processor itself (§4.4, §5.2.1): P·Vz drawn on the `cycle` or `word`
//! array.

use rtl_model::array::check_program;
use rtl_model::program::CReg;
use rtl_model::{Array, ArrayConfig, CycleArray, EquationSet, WordArray};

use csgpix_draw::compile::clip_scene_ops;
use csgpix_scene::clip_expr::Clip;

use crate::error::{Error, Result};
use crate::pixel_box::PixelBox;
use crate::slice::Mask;
use crate::slicer::Slicer;

/// What the processor shows for P·Vz, as a mask (pixels with a colour), and the clocks taken,
/// simulating the whole array.
pub fn array_mask(
    slicer: &Slicer,
    prim: usize,
    k: usize,
    cycle: bool,
    set: EquationSet,
) -> Result<(Mask, u64)> {
    let [w, h] = [slicer.grid.dims[0], slicer.grid.dims[1]];
    let all = PixelBox {
        x0: 0,
        y0: 0,
        x1: w,
        y1: h,
    };
    array_mask_in(slicer, prim, k, cycle, set, all)
}

/// [`array_mask`] simulating only the pixels of `bx`, as an array of that size whose DEPGEN
/// starts at the box's corner: every plane's Z0 becomes Z0 + x0·dZx + y0·dZy, modulo 2^N_D as
/// DEPGEN's sums are, so every simulated pixel receives the very word the whole array would
/// give it (pixels share nothing else). Pixels outside the box are left empty: the caller
/// knows from the footprint that P·Vz shows nothing there. The clocks are those of the
/// smaller array (its DEPGEN tree is shorter).
pub fn array_mask_in(
    slicer: &Slicer,
    prim: usize,
    k: usize,
    cycle: bool,
    set: EquationSet,
    bx: PixelBox,
) -> Result<(Mask, u64)> {
    let mut ops = slice_ops(slicer, prim, k)?;
    rtl_model::program::translate(&mut ops, bx.x0, bx.y0);
    let full = slicer.config();
    let cfg = ArrayConfig {
        width: bx.width(),
        height: bx.height(),
        // Only the clipping-stack levels the frame uses (its unused levels would hold 0).
        stack_depth: check_program(&ops, full.stack_depth)?,
        ..full
    };
    let mut arr: Box<dyn Array> = if cycle {
        Box::new(CycleArray::new(cfg, set))
    } else {
        Box::new(WordArray::new(cfg, set))
    };
    arr.run(&ops)?;
    let w = slicer.grid.dims[0];
    let mut mask = Mask::new(slicer.grid.slice_len());
    for y in 0..bx.height() {
        for x in 0..bx.width() {
            if arr.pixel(x, y).creg(CReg::G) != 0 {
                mask.set((bx.y0 + y) * w + bx.x0 + x, true);
            }
        }
    }
    Ok((mask, arr.cycles()))
}

/// The P·Vz program of primitive `prim` and slab `k` (§5.2.1: @(P)·Vz + @(Vz)·P).
pub fn slice_ops(slicer: &Slicer, prim: usize, k: usize) -> Result<Vec<rtl_model::Op>> {
    let p = &slicer.lists[prim];
    let lists = [p.clone(), slicer.slab_list(k, slicer.colours[prim] as u32)];
    let expr = Clip::And(Box::new(Clip::Obj(0)), Box::new(Clip::Obj(1)));
    let cfg = slicer.config();
    clip_scene_ops(&lists, &expr, &cfg.fmt, cfg.colour_bits)
        .map_err(|(_, error)| Error::Draw(csgpix_draw::Error::Solid { solid: prim, error }))
}
