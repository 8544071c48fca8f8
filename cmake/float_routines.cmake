# The software floating-point routines a compiler calls where the CPU (or the float ABI) has no
# instruction for the operation, and the C library's math functions: a symbol table (nm) line
# that defines or references one of these means the code uses floating point, whatever the
# disassembly shows. Included by check_no_float.cmake (the core's gate) and
# firmware/check_symbols.cmake (the images').
#   Arm EABI:  __aeabi_dadd, __aeabi_fmul, __aeabi_dcmplt, __aeabi_cdcmple, __aeabi_i2d,
#              __aeabi_ul2f, __aeabi_d2iz, __aeabi_h2f, ... (no integer __aeabi_ routine begins
#              with d, f, cd or cf, or converts to d or f);
#   libgcc (RISC-V, and Arm's hard-float builds for what the FPU lacks): __adddf3, __mulsf3,
#              __negdf2, __ltdf2, __unordsf2, __fixdfsi, __floatsidf, __extendsfdf2,
#              __truncdfsf2, __powidf2, __muldc3, the tf (128-bit long double) and hf forms,
#              and not the integer ones (__muldi3, __mulsi3, __divdi3, __cmpdi2, __negdi2);
#   libm:      sqrt, sin, atan2, floor, fabs, ... and their f and l forms.
set(HALOPLOT_FLOAT_ROUTINES
    "__aeabi_(c?[df][a-z0-9]+|u?[il]2[df]|h2f)|__(add|sub|mul|div)[sdtxhb]f3|__neg[sdtxhb]f2|__(eq|ne|lt|le|gt|ge|unord|cmp)[sdtxhb]f2|__fix(uns)?[sdtxhb]f[sdt]i|__float(un)?[sdt]i[sdtxhb]f|__extend[sdhb]f[sdtx]f2|__trunc[sdtx]f[sdhb]f2|__powi[sdtx]f2|__(mul|div)[sdtx]c3|(sqrt|cbrt|hypot|sin|cos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|exp|exp2|expm1|log|log2|log10|log1p|pow|floor|ceil|round|lround|llround|trunc|rint|lrint|nearbyint|fmod|remainder|fabs|fmin|fmax|fma|ldexp|frexp|modf|scalbn|copysign)[fl]?")
