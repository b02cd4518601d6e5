// The contactbench command: parses arguments and hands over to the app library.
#include "contactbench/app/cli.hpp"

int main(int argc, char** argv) {
  return contactbench::run_cli(argc, argv);
}
