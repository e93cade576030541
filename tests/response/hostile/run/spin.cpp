// Never returns.
static void Hostile() {
  volatile bool forever = true;
  while (forever) {
  }
}
