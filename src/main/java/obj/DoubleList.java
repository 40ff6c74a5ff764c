package obj;

import java.util.Arrays;

/** A growable double array: OBJ files hold millions of values, which boxed lists would triple in size. */
final class DoubleList {
    private double[] data = new double[48];
    private int size;

    void add(double value) {
        if (size == data.length) data = Arrays.copyOf(data, grown(size));
        data[size++] = value;
    }

    double get(int i) {
        return data[i];
    }

    boolean isZero(int triple) {
        return data[3 * triple] == 0 && data[3 * triple + 1] == 0 && data[3 * triple + 2] == 0;
    }

    int size() {
        return size;
    }

    int capacity() {
        return data.length;
    }

    double[] toArray() {
        return Arrays.copyOf(data, size);
    }

    /** Twice the capacity, without overflowing (the size checks stop a mesh long before the array limit). */
    static int grown(int capacity) {
        return (int) Math.min(Integer.MAX_VALUE - 8, 2L * capacity);
    }
}
