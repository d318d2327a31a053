// a*b + c, compiled with -march=haswell -ffp-contract=fast: every compiler here fuses it.
// The scan must find that FMA, or a clean scan of kernel_calls would prove nothing.
double fma_canary(double a, double b, double c) { return a * b + c; }
