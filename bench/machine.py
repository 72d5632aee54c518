"""What the benchmark pages say about the machine they were measured on."""
import platform


def cpu_name():
    """The processor's model name from /proc/cpuinfo (Linux), else what Python's platform module knows."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()
