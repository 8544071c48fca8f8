# The STM32F405's CPU: a Cortex-M4F. Its FPU is single precision only: double arithmetic would
# fall back to software, which the firmware gates reject. The core uses no floating point.
set(HALOPLOT_MCU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
