// Exits 0 when the CPU running it implements the x86-64-v3 instruction-set level (AVX2, FMA,
// BMI2, ...): the top-level CMakeLists.txt runs it at configure time to decide whether the
// build may target that level (HVI_HOST_ISA).
int main() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("x86-64-v3") ? 0 : 1;
}
