// The placeholder image for the STM32MP15: it starts, and parks the core. Its purpose is to keep the memory layout,
// the vector table and the toolchain building until the board support lands (issue #11).

int main() { return 0; }
