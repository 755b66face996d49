#pragma once

namespace hati
{
/**
 * Makes OpenBLAS use the kernels of the CPU it runs on where it does not
 * recognise it. OpenBLAS (Debian's dynamic-architecture build) picks its
 * kernels from the CPU's family and model; a virtual machine that reports a
 * generic model ("Intel Xeon Processor") gets the 2004 Prescott (SSE3)
 * kernels although the CPU has AVX2 and AVX-512. Measured on these
 * machines: a product of the 3D crane's reduction basis with 16 states 2.6x
 * faster with the SkylakeX kernels, MUMPS' substitutions (small matrix
 * products, most of their time in the Prescott kernels' packing) 2x.
 *
 * If OpenBLAS reports a core without AVX2 kernels (Prescott, Core2,
 * Penryn, Dunnington, Nehalem, Sandybridge) while the CPU has AVX-512
 * (F, CD, DQ, BW, VL: SkylakeX) or AVX2 and FMA (Haswell), this sets
 * `OPENBLAS_CORETYPE` and has OpenBLAS choose its kernels again
 * (`gotoblas_dynamic_quit()`, `gotoblas_dynamic_init()`: what it runs when
 * it is loaded, before `main`, reading that variable); where those entry
 * points are missing, it starts the program again with the same arguments
 * (which costs another start-up, 0.5 s here). Nothing changes
 * where the user set `OPENBLAS_CORETYPE`, where the BLAS is not OpenBLAS,
 * or where OpenBLAS recognised the CPU. Call it first in `main`, before
 * MPI is initialised. Results differ from the Prescott kernels' at
 * round-off.
 */
void select_blas_kernels(char **argv);
} // namespace hati
