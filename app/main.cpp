// bpde: the command-line program (FORMATS.md). Placeholder until the CLI lands.
int main() { return 0; }
