# Sourced by the scripts that run the nodes as separate processes: keeps their LCM traffic on
# this host.
#
#   enter_private_network SCRIPT ARGS...
#     re-executes SCRIPT ARGS... --in-namespace inside a private network namespace with multicast
#     routed to loopback, when one can be made (unshare -n) and we are not in one yet; else
#     returns.
#   LCM_DEFAULT_URL
#     UDP multicast with ttl=0 and a 4 MB receive buffer: a burst of small messages arriving
#     faster than a node reads them waits in the kernel's buffer instead of being dropped there
#     (the default, about 200 kB, holds a few hundred).

enter_private_network() {
  if [ -z "${in_namespace:-}" ] && unshare -n true 2>/dev/null; then
    exec unshare -n bash -c 'ip link set lo up multicast on &&
      ip route add 224.0.0.0/4 dev lo && exec "$0" "$@"' "$@" --in-namespace
  fi
}

export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
