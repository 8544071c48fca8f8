# The MPS2 AN385's CPU: a Cortex-M3, no FPU (the soft-float ABI; the core uses no floating
# point, and the firmware gates reject any software floating-point routine).
set(HALOPLOT_MCU_FLAGS "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
