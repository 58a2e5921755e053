module top$fetch(clock,start,valid,cur$0,cur$1,next$0,next$1,ext_addr$0,ext_addr$1,ext_data$0,ext_data$1,load_enable,load_module,load_address,load_data);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    output reg  valid;
    output reg  [15:0] cur$0;
    output reg  [15:0] cur$1;
    output reg  [15:0] next$0;
    output reg  [15:0] next$1;
    output reg  [31:0] ext_addr$0;
    output reg  [31:0] ext_addr$1;
    input wire  [15:0] ext_data$0;
    input wire  [15:0] ext_data$1;
    input wire  load_enable;
    input wire  [7:0] load_module;
    input wire  [31:0] load_address;
    input wire  [15:0] load_data;
    
    // Constant declarations
    localparam  external = 1'b1;
    localparam  index$0 = 16'h0;
    localparam  index$1 = 16'h1;
    localparam  module_id$0 = 8'h0;
    localparam  module_id$1 = 8'h1;
    localparam  buffer_id$0 = 2'b0;
    localparam  buffer_id$1 = 2'b1;
    localparam  buffer_id$2 = 2'b10;
    localparam  one = 16'h1;
    localparam  mask = 16'h1;
    localparam  shift = 16'h1;
    localparam  n_x = 16'h6e;
    localparam  n_y = 16'h100;
    localparam  n_k = 16'h100;
    localparam  row_words = 16'h37;
    localparam  plane_words = 16'h3700;
    localparam  u0 = 16'hfffe;
    localparam  v0 = 16'hff63;
    localparam  rays = 16'hcf;
    localparam  segments = 16'h80;
    
    // Stub signals
    reg  [15:0] memory$0$read_address;
    reg  memory$0$read_clock;
    wire  [15:0] memory$0$read_data;
    reg  [15:0] memory$0$write_address;
    reg  memory$0$write_clock;
    reg  [15:0] memory$0$write_data;
    reg  memory$0$write_enable;
    reg  [15:0] memory$1$read_address;
    reg  memory$1$read_clock;
    wire  [15:0] memory$1$read_data;
    reg  [15:0] memory$1$write_address;
    reg  memory$1$write_clock;
    reg  [15:0] memory$1$write_data;
    reg  memory$1$write_enable;
    reg  [15:0] buffer0$0$read_address;
    reg  buffer0$0$read_clock;
    wire  [15:0] buffer0$0$read_data;
    reg  [15:0] buffer0$0$write_address;
    reg  buffer0$0$write_clock;
    reg  [15:0] buffer0$0$write_data;
    reg  buffer0$0$write_enable;
    reg  [15:0] buffer0$1$read_address;
    reg  buffer0$1$read_clock;
    wire  [15:0] buffer0$1$read_data;
    reg  [15:0] buffer0$1$write_address;
    reg  buffer0$1$write_clock;
    reg  [15:0] buffer0$1$write_data;
    reg  buffer0$1$write_enable;
    reg  [15:0] buffer1$0$read_address;
    reg  buffer1$0$read_clock;
    wire  [15:0] buffer1$0$read_data;
    reg  [15:0] buffer1$0$write_address;
    reg  buffer1$0$write_clock;
    reg  [15:0] buffer1$0$write_data;
    reg  buffer1$0$write_enable;
    reg  [15:0] buffer1$1$read_address;
    reg  buffer1$1$read_clock;
    wire  [15:0] buffer1$1$read_data;
    reg  [15:0] buffer1$1$write_address;
    reg  buffer1$1$write_clock;
    reg  [15:0] buffer1$1$write_data;
    reg  buffer1$1$write_enable;
    reg  [15:0] buffer2$0$read_address;
    reg  buffer2$0$read_clock;
    wire  [15:0] buffer2$0$read_data;
    reg  [15:0] buffer2$0$write_address;
    reg  buffer2$0$write_clock;
    reg  [15:0] buffer2$0$write_data;
    reg  buffer2$0$write_enable;
    reg  [15:0] buffer2$1$read_address;
    reg  buffer2$1$read_clock;
    wire  [15:0] buffer2$1$read_data;
    reg  [15:0] buffer2$1$write_address;
    reg  buffer2$1$write_clock;
    reg  [15:0] buffer2$1$write_data;
    reg  buffer2$1$write_enable;
    reg  [9:0] pos_x$address;
    wire  [15:0] pos_x$data;
    reg  [9:0] pos_y$address;
    wire  [15:0] pos_y$data;
    reg  schedule$clock;
    reg  schedule$start;
    wire  schedule$writing;
    wire  [15:0] schedule$plane;
    wire  [15:0] schedule$chunk;
    wire  [15:0] schedule$period;
    wire  [1:0] schedule$write_buffer;
    wire  schedule$reading;
    wire  [15:0] schedule$ray;
    wire  [15:0] schedule$segment;
    wire  [1:0] schedule$cur_buffer;
    wire  [1:0] schedule$next_buffer;
    reg  inside_q$0$d;
    wire  inside_q$0$q;
    reg  inside_q$0$clock;
    reg  inside_q$1$d;
    wire  inside_q$1$q;
    reg  inside_q$1$clock;
    reg  [15:0] rotate_q$d;
    wire  [15:0] rotate_q$q;
    reg  rotate_q$clock;
    reg  [15:0] plane_q$d;
    wire  [15:0] plane_q$q;
    reg  plane_q$clock;
    reg  [15:0] chunk_q$d;
    wire  [15:0] chunk_q$q;
    reg  chunk_q$clock;
    reg  write_q$d;
    wire  write_q$q;
    reg  write_q$clock;
    reg  [1:0] buffer_q$d;
    wire  [1:0] buffer_q$q;
    reg  buffer_q$clock;
    reg  read_q$d;
    wire  read_q$q;
    reg  read_q$clock;
    reg  [15:0] lane_q$d;
    wire  [15:0] lane_q$q;
    reg  lane_q$clock;
    reg  [1:0] cur_q$d;
    wire  [1:0] cur_q$q;
    reg  cur_q$clock;
    reg  [1:0] next_q$d;
    wire  [1:0] next_q$q;
    reg  next_q$clock;
    
    // Local signals
    reg  [15:0] word$0;
    reg  [15:0] word$1;
    reg  [15:0] row;
    reg  [15:0] x0;
    reg  [15:0] base;
    reg  [15:0] xm$0;
    reg  [15:0] xm$1;
    reg  [15:0] column$0;
    reg  [15:0] column$1;
    reg  inside$0;
    reg  inside$1;
    reg  [15:0] plane_segment;
    reg  [31:0] address$0;
    reg  [31:0] address$1;
    reg  [15:0] ray$0;
    reg  [15:0] ray$1;
    reg  [15:0] value$0;
    reg  [15:0] value$1;
    reg  [31:0] write_address$0;
    reg  [31:0] write_address$1;
    reg  [31:0] read_address;
    
    // Sub module instances
    top$fetch$memory$0 memory$0(
        .read_address(memory$0$read_address),
        .read_clock(memory$0$read_clock),
        .read_data(memory$0$read_data),
        .write_address(memory$0$write_address),
        .write_clock(memory$0$write_clock),
        .write_data(memory$0$write_data),
        .write_enable(memory$0$write_enable)
    );
    top$fetch$memory$1 memory$1(
        .read_address(memory$1$read_address),
        .read_clock(memory$1$read_clock),
        .read_data(memory$1$read_data),
        .write_address(memory$1$write_address),
        .write_clock(memory$1$write_clock),
        .write_data(memory$1$write_data),
        .write_enable(memory$1$write_enable)
    );
    top$fetch$buffer0$0 buffer0$0(
        .read_address(buffer0$0$read_address),
        .read_clock(buffer0$0$read_clock),
        .read_data(buffer0$0$read_data),
        .write_address(buffer0$0$write_address),
        .write_clock(buffer0$0$write_clock),
        .write_data(buffer0$0$write_data),
        .write_enable(buffer0$0$write_enable)
    );
    top$fetch$buffer0$1 buffer0$1(
        .read_address(buffer0$1$read_address),
        .read_clock(buffer0$1$read_clock),
        .read_data(buffer0$1$read_data),
        .write_address(buffer0$1$write_address),
        .write_clock(buffer0$1$write_clock),
        .write_data(buffer0$1$write_data),
        .write_enable(buffer0$1$write_enable)
    );
    top$fetch$buffer1$0 buffer1$0(
        .read_address(buffer1$0$read_address),
        .read_clock(buffer1$0$read_clock),
        .read_data(buffer1$0$read_data),
        .write_address(buffer1$0$write_address),
        .write_clock(buffer1$0$write_clock),
        .write_data(buffer1$0$write_data),
        .write_enable(buffer1$0$write_enable)
    );
    top$fetch$buffer1$1 buffer1$1(
        .read_address(buffer1$1$read_address),
        .read_clock(buffer1$1$read_clock),
        .read_data(buffer1$1$read_data),
        .write_address(buffer1$1$write_address),
        .write_clock(buffer1$1$write_clock),
        .write_data(buffer1$1$write_data),
        .write_enable(buffer1$1$write_enable)
    );
    top$fetch$buffer2$0 buffer2$0(
        .read_address(buffer2$0$read_address),
        .read_clock(buffer2$0$read_clock),
        .read_data(buffer2$0$read_data),
        .write_address(buffer2$0$write_address),
        .write_clock(buffer2$0$write_clock),
        .write_data(buffer2$0$write_data),
        .write_enable(buffer2$0$write_enable)
    );
    top$fetch$buffer2$1 buffer2$1(
        .read_address(buffer2$1$read_address),
        .read_clock(buffer2$1$read_clock),
        .read_data(buffer2$1$read_data),
        .write_address(buffer2$1$write_address),
        .write_clock(buffer2$1$write_clock),
        .write_data(buffer2$1$write_data),
        .write_enable(buffer2$1$write_enable)
    );
    top$fetch$pos_x pos_x(
        .address(pos_x$address),
        .data(pos_x$data)
    );
    top$fetch$pos_y pos_y(
        .address(pos_y$address),
        .data(pos_y$data)
    );
    top$fetch$schedule schedule(
        .clock(schedule$clock),
        .start(schedule$start),
        .writing(schedule$writing),
        .plane(schedule$plane),
        .chunk(schedule$chunk),
        .period(schedule$period),
        .write_buffer(schedule$write_buffer),
        .reading(schedule$reading),
        .ray(schedule$ray),
        .segment(schedule$segment),
        .cur_buffer(schedule$cur_buffer),
        .next_buffer(schedule$next_buffer)
    );
    top$fetch$inside_q$0 inside_q$0(
        .d(inside_q$0$d),
        .q(inside_q$0$q),
        .clock(inside_q$0$clock)
    );
    top$fetch$inside_q$1 inside_q$1(
        .d(inside_q$1$d),
        .q(inside_q$1$q),
        .clock(inside_q$1$clock)
    );
    top$fetch$rotate_q rotate_q(
        .d(rotate_q$d),
        .q(rotate_q$q),
        .clock(rotate_q$clock)
    );
    top$fetch$plane_q plane_q(
        .d(plane_q$d),
        .q(plane_q$q),
        .clock(plane_q$clock)
    );
    top$fetch$chunk_q chunk_q(
        .d(chunk_q$d),
        .q(chunk_q$q),
        .clock(chunk_q$clock)
    );
    top$fetch$write_q write_q(
        .d(write_q$d),
        .q(write_q$q),
        .clock(write_q$clock)
    );
    top$fetch$buffer_q buffer_q(
        .d(buffer_q$d),
        .q(buffer_q$q),
        .clock(buffer_q$clock)
    );
    top$fetch$read_q read_q(
        .d(read_q$d),
        .q(read_q$q),
        .clock(read_q$clock)
    );
    top$fetch$lane_q lane_q(
        .d(lane_q$d),
        .q(lane_q$q),
        .clock(lane_q$clock)
    );
    top$fetch$cur_q cur_q(
        .d(cur_q$d),
        .q(cur_q$q),
        .clock(cur_q$clock)
    );
    top$fetch$next_q next_q(
        .d(next_q$d),
        .q(next_q$q),
        .clock(next_q$clock)
    );
    
    // Update code
    always @(*) begin
        rotate_q$clock = clock;
        plane_q$clock = clock;
        chunk_q$clock = clock;
        write_q$clock = clock;
        buffer_q$clock = clock;
        read_q$clock = clock;
        lane_q$clock = clock;
        cur_q$clock = clock;
        next_q$clock = clock;
        rotate_q$d = rotate_q$q;
        plane_q$d = plane_q$q;
        chunk_q$d = chunk_q$q;
        write_q$d = write_q$q;
        buffer_q$d = buffer_q$q;
        read_q$d = read_q$q;
        lane_q$d = lane_q$q;
        cur_q$d = cur_q$q;
        next_q$d = next_q$q;
        schedule$clock = clock;
        schedule$start = start;
        pos_x$address = schedule$plane[('h0)+:(10)];
        pos_y$address = schedule$plane[('h0)+:(10)];
        row = v0 + schedule$period + pos_y$data;
        x0 = u0 + pos_x$data + (schedule$chunk << shift);
        base = (x0 + row + schedule$plane) & mask;
        memory$0$read_clock = clock;
        memory$0$write_clock = clock;
        memory$0$write_enable = load_enable & (load_module == module_id$0) & ~external;
        memory$0$write_address = load_address[('h0)+:(16)];
        memory$0$write_data = load_data;
        xm$0 = x0 + ((index$0 - base) & mask);
        inside$0 = ~xm$0['hf] & (xm$0 < n_x) & ~row['hf] & (row < n_y) & (schedule$plane < n_k);
        column$0 = xm$0 >> shift;
        address$0 = column$0 * one + row * row_words + schedule$plane * plane_words;
        memory$0$read_address = 'h0;
        ext_addr$0 = 'h0;
        if (inside$0 & ~external) begin
            memory$0$read_address = address$0[('h0)+:(16)];
        end
        if (inside$0 & external) begin
            ext_addr$0 = address$0;
        end
        word$0 = memory$0$read_data;
        if (external) begin
            word$0 = ext_data$0;
        end
        inside_q$0$clock = clock;
        inside_q$0$d = inside$0;
        memory$1$read_clock = clock;
        memory$1$write_clock = clock;
        memory$1$write_enable = load_enable & (load_module == module_id$1) & ~external;
        memory$1$write_address = load_address[('h0)+:(16)];
        memory$1$write_data = load_data;
        xm$1 = x0 + ((index$1 - base) & mask);
        inside$1 = ~xm$1['hf] & (xm$1 < n_x) & ~row['hf] & (row < n_y) & (schedule$plane < n_k);
        column$1 = xm$1 >> shift;
        address$1 = column$1 * one + row * row_words + schedule$plane * plane_words;
        memory$1$read_address = 'h0;
        ext_addr$1 = 'h0;
        if (inside$1 & ~external) begin
            memory$1$read_address = address$1[('h0)+:(16)];
        end
        if (inside$1 & external) begin
            ext_addr$1 = address$1;
        end
        word$1 = memory$1$read_data;
        if (external) begin
            word$1 = ext_data$1;
        end
        inside_q$1$clock = clock;
        inside_q$1$d = inside$1;
        rotate_q$d = (x0 + row) & mask;
        plane_q$d = schedule$plane;
        chunk_q$d = schedule$chunk;
        write_q$d = schedule$writing;
        plane_segment = plane_q$q >> shift;
        buffer_q$d = schedule$write_buffer;
        value$0 = 'h0;
        if ((((index$0 + rotate_q$q) & mask) == index$0) & inside_q$0$q) begin
            value$0 = word$0;
        end
        if ((((index$0 + rotate_q$q) & mask) == index$1) & inside_q$1$q) begin
            value$0 = word$1;
        end
        ray$0 = (chunk_q$q << shift) + ((index$0 - plane_q$q) & mask);
        write_address$0 = ray$0 * segments + 32'(plane_segment);
        buffer0$0$write_clock = clock;
        buffer1$0$write_clock = clock;
        buffer2$0$write_clock = clock;
        buffer0$0$write_address = write_address$0[('h0)+:(16)];
        buffer1$0$write_address = write_address$0[('h0)+:(16)];
        buffer2$0$write_address = write_address$0[('h0)+:(16)];
        buffer0$0$write_data = value$0;
        buffer1$0$write_data = value$0;
        buffer2$0$write_data = value$0;
        buffer0$0$write_enable = write_q$q & (ray$0 < rays) & (buffer_q$q == buffer_id$0);
        buffer1$0$write_enable = write_q$q & (ray$0 < rays) & (buffer_q$q == buffer_id$1);
        buffer2$0$write_enable = write_q$q & (ray$0 < rays) & (buffer_q$q == buffer_id$2);
        value$1 = 'h0;
        if ((((index$1 + rotate_q$q) & mask) == index$0) & inside_q$0$q) begin
            value$1 = word$0;
        end
        if ((((index$1 + rotate_q$q) & mask) == index$1) & inside_q$1$q) begin
            value$1 = word$1;
        end
        ray$1 = (chunk_q$q << shift) + ((index$1 - plane_q$q) & mask);
        write_address$1 = ray$1 * segments + 32'(plane_segment);
        buffer0$1$write_clock = clock;
        buffer1$1$write_clock = clock;
        buffer2$1$write_clock = clock;
        buffer0$1$write_address = write_address$1[('h0)+:(16)];
        buffer1$1$write_address = write_address$1[('h0)+:(16)];
        buffer2$1$write_address = write_address$1[('h0)+:(16)];
        buffer0$1$write_data = value$1;
        buffer1$1$write_data = value$1;
        buffer2$1$write_data = value$1;
        buffer0$1$write_enable = write_q$q & (ray$1 < rays) & (buffer_q$q == buffer_id$0);
        buffer1$1$write_enable = write_q$q & (ray$1 < rays) & (buffer_q$q == buffer_id$1);
        buffer2$1$write_enable = write_q$q & (ray$1 < rays) & (buffer_q$q == buffer_id$2);
        read_address = 'h0;
        if (schedule$reading) begin
            read_address = schedule$ray * segments + 32'(schedule$segment);
        end
        read_q$d = schedule$reading;
        lane_q$d = schedule$ray & mask;
        cur_q$d = schedule$cur_buffer;
        next_q$d = schedule$next_buffer;
        buffer0$0$read_clock = clock;
        buffer1$0$read_clock = clock;
        buffer2$0$read_clock = clock;
        buffer0$0$read_address = read_address[('h0)+:(16)];
        buffer1$0$read_address = read_address[('h0)+:(16)];
        buffer2$0$read_address = read_address[('h0)+:(16)];
        buffer0$1$read_clock = clock;
        buffer1$1$read_clock = clock;
        buffer2$1$read_clock = clock;
        buffer0$1$read_address = read_address[('h0)+:(16)];
        buffer1$1$read_address = read_address[('h0)+:(16)];
        buffer2$1$read_address = read_address[('h0)+:(16)];
        cur$0 = 'h0;
        next$0 = 'h0;
        if (((index$0 + lane_q$q) & mask) == index$0) begin
            if (cur_q$q == buffer_id$0) begin
                cur$0 = buffer0$0$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$0 = buffer1$0$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$0 = buffer2$0$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$0 = buffer0$0$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$0 = buffer1$0$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$0 = buffer2$0$read_data;
            end
        end
        if (((index$0 + lane_q$q) & mask) == index$1) begin
            if (cur_q$q == buffer_id$0) begin
                cur$0 = buffer0$1$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$0 = buffer1$1$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$0 = buffer2$1$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$0 = buffer0$1$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$0 = buffer1$1$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$0 = buffer2$1$read_data;
            end
        end
        cur$1 = 'h0;
        next$1 = 'h0;
        if (((index$1 + lane_q$q) & mask) == index$0) begin
            if (cur_q$q == buffer_id$0) begin
                cur$1 = buffer0$0$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$1 = buffer1$0$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$1 = buffer2$0$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$1 = buffer0$0$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$1 = buffer1$0$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$1 = buffer2$0$read_data;
            end
        end
        if (((index$1 + lane_q$q) & mask) == index$1) begin
            if (cur_q$q == buffer_id$0) begin
                cur$1 = buffer0$1$read_data;
            end
            if (cur_q$q == buffer_id$1) begin
                cur$1 = buffer1$1$read_data;
            end
            if (cur_q$q == buffer_id$2) begin
                cur$1 = buffer2$1$read_data;
            end
            if (next_q$q == buffer_id$0) begin
                next$1 = buffer0$1$read_data;
            end
            if (next_q$q == buffer_id$1) begin
                next$1 = buffer1$1$read_data;
            end
            if (next_q$q == buffer_id$2) begin
                next$1 = buffer2$1$read_data;
            end
        end
        valid = read_q$q;
    end
    
endmodule // top$fetch
module top$fetch$buffer0$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer0$0
module top$fetch$buffer0$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer0$1
module top$fetch$buffer1$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer1$0
module top$fetch$buffer1$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer1$1
module top$fetch$buffer2$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer2$0
module top$fetch$buffer2$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[26495:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[14:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[14:0]] <= write_data;
       end
    end
endmodule // top$fetch$buffer2$1
module top$fetch$buffer_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$buffer_q
module top$fetch$chunk_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$chunk_q
module top$fetch$cur_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$cur_q
module top$fetch$inside_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$inside_q$0
module top$fetch$inside_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$inside_q$1
module top$fetch$lane_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$lane_q
module top$fetch$memory$0(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[0:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= write_data;
       end
    end
endmodule // top$fetch$memory$0
module top$fetch$memory$1(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [15:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [15:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [15:0] mem[1:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[0:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[0:0]] <= write_data;
       end
    end
endmodule // top$fetch$memory$1
module top$fetch$next_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$next_q
module top$fetch$plane_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$plane_q
module top$fetch$pos_x(address,data);
    
    // Module arguments
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        10'b0: data = 16'h0;
      10'b1: data = 16'hffff;
      10'b10: data = 16'hffff;
      10'b11: data = 16'hfffe;
      10'b100: data = 16'hfffe;
      10'b101: data = 16'hfffe;
      10'b110: data = 16'hfffd;
      10'b111: data = 16'hfffd;
      10'b1000: data = 16'hfffd;
      10'b1001: data = 16'hfffc;
      10'b1010: data = 16'hfffc;
      10'b1011: data = 16'hfffc;
      10'b1100: data = 16'hfffb;
      10'b1101: data = 16'hfffb;
      10'b1110: data = 16'hfffa;
      10'b1111: data = 16'hfffa;
      10'b10000: data = 16'hfffa;
      10'b10001: data = 16'hfff9;
      10'b10010: data = 16'hfff9;
      10'b10011: data = 16'hfff9;
      10'b10100: data = 16'hfff8;
      10'b10101: data = 16'hfff8;
      10'b10110: data = 16'hfff8;
      10'b10111: data = 16'hfff7;
      10'b11000: data = 16'hfff7;
      10'b11001: data = 16'hfff6;
      10'b11010: data = 16'hfff6;
      10'b11011: data = 16'hfff6;
      10'b11100: data = 16'hfff5;
      10'b11101: data = 16'hfff5;
      10'b11110: data = 16'hfff5;
      10'b11111: data = 16'hfff4;
      10'b100000: data = 16'hfff4;
      10'b100001: data = 16'hfff4;
      10'b100010: data = 16'hfff3;
      10'b100011: data = 16'hfff3;
      10'b100100: data = 16'hfff2;
      10'b100101: data = 16'hfff2;
      10'b100110: data = 16'hfff2;
      10'b100111: data = 16'hfff1;
      10'b101000: data = 16'hfff1;
      10'b101001: data = 16'hfff1;
      10'b101010: data = 16'hfff0;
      10'b101011: data = 16'hfff0;
      10'b101100: data = 16'hfff0;
      10'b101101: data = 16'hffef;
      10'b101110: data = 16'hffef;
      10'b101111: data = 16'hffee;
      10'b110000: data = 16'hffee;
      10'b110001: data = 16'hffee;
      10'b110010: data = 16'hffed;
      10'b110011: data = 16'hffed;
      10'b110100: data = 16'hffed;
      10'b110101: data = 16'hffec;
      10'b110110: data = 16'hffec;
      10'b110111: data = 16'hffec;
      10'b111000: data = 16'hffeb;
      10'b111001: data = 16'hffeb;
      10'b111010: data = 16'hffea;
      10'b111011: data = 16'hffea;
      10'b111100: data = 16'hffea;
      10'b111101: data = 16'hffe9;
      10'b111110: data = 16'hffe9;
      10'b111111: data = 16'hffe9;
      10'b1000000: data = 16'hffe8;
      10'b1000001: data = 16'hffe8;
      10'b1000010: data = 16'hffe8;
      10'b1000011: data = 16'hffe7;
      10'b1000100: data = 16'hffe7;
      10'b1000101: data = 16'hffe6;
      10'b1000110: data = 16'hffe6;
      10'b1000111: data = 16'hffe6;
      10'b1001000: data = 16'hffe5;
      10'b1001001: data = 16'hffe5;
      10'b1001010: data = 16'hffe5;
      10'b1001011: data = 16'hffe4;
      10'b1001100: data = 16'hffe4;
      10'b1001101: data = 16'hffe4;
      10'b1001110: data = 16'hffe3;
      10'b1001111: data = 16'hffe3;
      10'b1010000: data = 16'hffe2;
      10'b1010001: data = 16'hffe2;
      10'b1010010: data = 16'hffe2;
      10'b1010011: data = 16'hffe1;
      10'b1010100: data = 16'hffe1;
      10'b1010101: data = 16'hffe1;
      10'b1010110: data = 16'hffe0;
      10'b1010111: data = 16'hffe0;
      10'b1011000: data = 16'hffe0;
      10'b1011001: data = 16'hffdf;
      10'b1011010: data = 16'hffdf;
      10'b1011011: data = 16'hffde;
      10'b1011100: data = 16'hffde;
      10'b1011101: data = 16'hffde;
      10'b1011110: data = 16'hffdd;
      10'b1011111: data = 16'hffdd;
      10'b1100000: data = 16'hffdd;
      10'b1100001: data = 16'hffdc;
      10'b1100010: data = 16'hffdc;
      10'b1100011: data = 16'hffdc;
      10'b1100100: data = 16'hffdb;
      10'b1100101: data = 16'hffdb;
      10'b1100110: data = 16'hffda;
      10'b1100111: data = 16'hffda;
      10'b1101000: data = 16'hffda;
      10'b1101001: data = 16'hffd9;
      10'b1101010: data = 16'hffd9;
      10'b1101011: data = 16'hffd9;
      10'b1101100: data = 16'hffd8;
      10'b1101101: data = 16'hffd8;
      10'b1101110: data = 16'hffd8;
      10'b1101111: data = 16'hffd7;
      10'b1110000: data = 16'hffd7;
      10'b1110001: data = 16'hffd6;
      10'b1110010: data = 16'hffd6;
      10'b1110011: data = 16'hffd6;
      10'b1110100: data = 16'hffd5;
      10'b1110101: data = 16'hffd5;
      10'b1110110: data = 16'hffd5;
      10'b1110111: data = 16'hffd4;
      10'b1111000: data = 16'hffd4;
      10'b1111001: data = 16'hffd4;
      10'b1111010: data = 16'hffd3;
      10'b1111011: data = 16'hffd3;
      10'b1111100: data = 16'hffd2;
      10'b1111101: data = 16'hffd2;
      10'b1111110: data = 16'hffd2;
      10'b1111111: data = 16'hffd1;
      10'b10000000: data = 16'hffd1;
      10'b10000001: data = 16'hffd1;
      10'b10000010: data = 16'hffd0;
      10'b10000011: data = 16'hffd0;
      10'b10000100: data = 16'hffd0;
      10'b10000101: data = 16'hffcf;
      10'b10000110: data = 16'hffcf;
      10'b10000111: data = 16'hffce;
      10'b10001000: data = 16'hffce;
      10'b10001001: data = 16'hffce;
      10'b10001010: data = 16'hffcd;
      10'b10001011: data = 16'hffcd;
      10'b10001100: data = 16'hffcd;
      10'b10001101: data = 16'hffcc;
      10'b10001110: data = 16'hffcc;
      10'b10001111: data = 16'hffcc;
      10'b10010000: data = 16'hffcb;
      10'b10010001: data = 16'hffcb;
      10'b10010010: data = 16'hffca;
      10'b10010011: data = 16'hffca;
      10'b10010100: data = 16'hffca;
      10'b10010101: data = 16'hffc9;
      10'b10010110: data = 16'hffc9;
      10'b10010111: data = 16'hffc9;
      10'b10011000: data = 16'hffc8;
      10'b10011001: data = 16'hffc8;
      10'b10011010: data = 16'hffc8;
      10'b10011011: data = 16'hffc7;
      10'b10011100: data = 16'hffc7;
      10'b10011101: data = 16'hffc6;
      10'b10011110: data = 16'hffc6;
      10'b10011111: data = 16'hffc6;
      10'b10100000: data = 16'hffc5;
      10'b10100001: data = 16'hffc5;
      10'b10100010: data = 16'hffc5;
      10'b10100011: data = 16'hffc4;
      10'b10100100: data = 16'hffc4;
      10'b10100101: data = 16'hffc4;
      10'b10100110: data = 16'hffc3;
      10'b10100111: data = 16'hffc3;
      10'b10101000: data = 16'hffc2;
      10'b10101001: data = 16'hffc2;
      10'b10101010: data = 16'hffc2;
      10'b10101011: data = 16'hffc1;
      10'b10101100: data = 16'hffc1;
      10'b10101101: data = 16'hffc1;
      10'b10101110: data = 16'hffc0;
      10'b10101111: data = 16'hffc0;
      10'b10110000: data = 16'hffc0;
      10'b10110001: data = 16'hffbf;
      10'b10110010: data = 16'hffbf;
      10'b10110011: data = 16'hffbe;
      10'b10110100: data = 16'hffbe;
      10'b10110101: data = 16'hffbe;
      10'b10110110: data = 16'hffbd;
      10'b10110111: data = 16'hffbd;
      10'b10111000: data = 16'hffbd;
      10'b10111001: data = 16'hffbc;
      10'b10111010: data = 16'hffbc;
      10'b10111011: data = 16'hffbc;
      10'b10111100: data = 16'hffbb;
      10'b10111101: data = 16'hffbb;
      10'b10111110: data = 16'hffba;
      10'b10111111: data = 16'hffba;
      10'b11000000: data = 16'hffba;
      10'b11000001: data = 16'hffb9;
      10'b11000010: data = 16'hffb9;
      10'b11000011: data = 16'hffb9;
      10'b11000100: data = 16'hffb8;
      10'b11000101: data = 16'hffb8;
      10'b11000110: data = 16'hffb8;
      10'b11000111: data = 16'hffb7;
      10'b11001000: data = 16'hffb7;
      10'b11001001: data = 16'hffb6;
      10'b11001010: data = 16'hffb6;
      10'b11001011: data = 16'hffb6;
      10'b11001100: data = 16'hffb5;
      10'b11001101: data = 16'hffb5;
      10'b11001110: data = 16'hffb5;
      10'b11001111: data = 16'hffb4;
      10'b11010000: data = 16'hffb4;
      10'b11010001: data = 16'hffb4;
      10'b11010010: data = 16'hffb3;
      10'b11010011: data = 16'hffb3;
      10'b11010100: data = 16'hffb2;
      10'b11010101: data = 16'hffb2;
      10'b11010110: data = 16'hffb2;
      10'b11010111: data = 16'hffb1;
      10'b11011000: data = 16'hffb1;
      10'b11011001: data = 16'hffb1;
      10'b11011010: data = 16'hffb0;
      10'b11011011: data = 16'hffb0;
      10'b11011100: data = 16'hffb0;
      10'b11011101: data = 16'hffaf;
      10'b11011110: data = 16'hffaf;
      10'b11011111: data = 16'hffae;
      10'b11100000: data = 16'hffae;
      10'b11100001: data = 16'hffae;
      10'b11100010: data = 16'hffad;
      10'b11100011: data = 16'hffad;
      10'b11100100: data = 16'hffad;
      10'b11100101: data = 16'hffac;
      10'b11100110: data = 16'hffac;
      10'b11100111: data = 16'hffac;
      10'b11101000: data = 16'hffab;
      10'b11101001: data = 16'hffab;
      10'b11101010: data = 16'hffaa;
      10'b11101011: data = 16'hffaa;
      10'b11101100: data = 16'hffaa;
      10'b11101101: data = 16'hffa9;
      10'b11101110: data = 16'hffa9;
      10'b11101111: data = 16'hffa9;
      10'b11110000: data = 16'hffa8;
      10'b11110001: data = 16'hffa8;
      10'b11110010: data = 16'hffa8;
      10'b11110011: data = 16'hffa7;
      10'b11110100: data = 16'hffa7;
      10'b11110101: data = 16'hffa6;
      10'b11110110: data = 16'hffa6;
      10'b11110111: data = 16'hffa6;
      10'b11111000: data = 16'hffa5;
      10'b11111001: data = 16'hffa5;
      10'b11111010: data = 16'hffa5;
      10'b11111011: data = 16'hffa4;
      10'b11111100: data = 16'hffa4;
      10'b11111101: data = 16'hffa4;
      10'b11111110: data = 16'hffa3;
      10'b11111111: data = 16'hffa3;
      10'b100000000: data = 16'hffa3;
      default: data = 16'h0;
    endcase
            
endmodule // top$fetch$pos_x
module top$fetch$pos_y(address,data);
    
    // Module arguments
    input wire  [9:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        10'b0: data = 16'h0;
      10'b1: data = 16'h0;
      10'b10: data = 16'h1;
      10'b11: data = 16'h1;
      10'b100: data = 16'h2;
      10'b101: data = 16'h3;
      10'b110: data = 16'h3;
      10'b111: data = 16'h4;
      10'b1000: data = 16'h4;
      10'b1001: data = 16'h5;
      10'b1010: data = 16'h6;
      10'b1011: data = 16'h6;
      10'b1100: data = 16'h7;
      10'b1101: data = 16'h7;
      10'b1110: data = 16'h8;
      10'b1111: data = 16'h9;
      10'b10000: data = 16'h9;
      10'b10001: data = 16'ha;
      10'b10010: data = 16'hb;
      10'b10011: data = 16'hb;
      10'b10100: data = 16'hc;
      10'b10101: data = 16'hc;
      10'b10110: data = 16'hd;
      10'b10111: data = 16'he;
      10'b11000: data = 16'he;
      10'b11001: data = 16'hf;
      10'b11010: data = 16'hf;
      10'b11011: data = 16'h10;
      10'b11100: data = 16'h11;
      10'b11101: data = 16'h11;
      10'b11110: data = 16'h12;
      10'b11111: data = 16'h13;
      10'b100000: data = 16'h13;
      10'b100001: data = 16'h14;
      10'b100010: data = 16'h14;
      10'b100011: data = 16'h15;
      10'b100100: data = 16'h16;
      10'b100101: data = 16'h16;
      10'b100110: data = 16'h17;
      10'b100111: data = 16'h17;
      10'b101000: data = 16'h18;
      10'b101001: data = 16'h19;
      10'b101010: data = 16'h19;
      10'b101011: data = 16'h1a;
      10'b101100: data = 16'h1a;
      10'b101101: data = 16'h1b;
      10'b101110: data = 16'h1c;
      10'b101111: data = 16'h1c;
      10'b110000: data = 16'h1d;
      10'b110001: data = 16'h1e;
      10'b110010: data = 16'h1e;
      10'b110011: data = 16'h1f;
      10'b110100: data = 16'h1f;
      10'b110101: data = 16'h20;
      10'b110110: data = 16'h21;
      10'b110111: data = 16'h21;
      10'b111000: data = 16'h22;
      10'b111001: data = 16'h22;
      10'b111010: data = 16'h23;
      10'b111011: data = 16'h24;
      10'b111100: data = 16'h24;
      10'b111101: data = 16'h25;
      10'b111110: data = 16'h26;
      10'b111111: data = 16'h26;
      10'b1000000: data = 16'h27;
      10'b1000001: data = 16'h27;
      10'b1000010: data = 16'h28;
      10'b1000011: data = 16'h29;
      10'b1000100: data = 16'h29;
      10'b1000101: data = 16'h2a;
      10'b1000110: data = 16'h2a;
      10'b1000111: data = 16'h2b;
      10'b1001000: data = 16'h2c;
      10'b1001001: data = 16'h2c;
      10'b1001010: data = 16'h2d;
      10'b1001011: data = 16'h2d;
      10'b1001100: data = 16'h2e;
      10'b1001101: data = 16'h2f;
      10'b1001110: data = 16'h2f;
      10'b1001111: data = 16'h30;
      10'b1010000: data = 16'h31;
      10'b1010001: data = 16'h31;
      10'b1010010: data = 16'h32;
      10'b1010011: data = 16'h32;
      10'b1010100: data = 16'h33;
      10'b1010101: data = 16'h34;
      10'b1010110: data = 16'h34;
      10'b1010111: data = 16'h35;
      10'b1011000: data = 16'h35;
      10'b1011001: data = 16'h36;
      10'b1011010: data = 16'h37;
      10'b1011011: data = 16'h37;
      10'b1011100: data = 16'h38;
      10'b1011101: data = 16'h39;
      10'b1011110: data = 16'h39;
      10'b1011111: data = 16'h3a;
      10'b1100000: data = 16'h3a;
      10'b1100001: data = 16'h3b;
      10'b1100010: data = 16'h3c;
      10'b1100011: data = 16'h3c;
      10'b1100100: data = 16'h3d;
      10'b1100101: data = 16'h3d;
      10'b1100110: data = 16'h3e;
      10'b1100111: data = 16'h3f;
      10'b1101000: data = 16'h3f;
      10'b1101001: data = 16'h40;
      10'b1101010: data = 16'h41;
      10'b1101011: data = 16'h41;
      10'b1101100: data = 16'h42;
      10'b1101101: data = 16'h42;
      10'b1101110: data = 16'h43;
      10'b1101111: data = 16'h44;
      10'b1110000: data = 16'h44;
      10'b1110001: data = 16'h45;
      10'b1110010: data = 16'h45;
      10'b1110011: data = 16'h46;
      10'b1110100: data = 16'h47;
      10'b1110101: data = 16'h47;
      10'b1110110: data = 16'h48;
      10'b1110111: data = 16'h48;
      10'b1111000: data = 16'h49;
      10'b1111001: data = 16'h4a;
      10'b1111010: data = 16'h4a;
      10'b1111011: data = 16'h4b;
      10'b1111100: data = 16'h4c;
      10'b1111101: data = 16'h4c;
      10'b1111110: data = 16'h4d;
      10'b1111111: data = 16'h4d;
      10'b10000000: data = 16'h4e;
      10'b10000001: data = 16'h4f;
      10'b10000010: data = 16'h4f;
      10'b10000011: data = 16'h50;
      10'b10000100: data = 16'h50;
      10'b10000101: data = 16'h51;
      10'b10000110: data = 16'h52;
      10'b10000111: data = 16'h52;
      10'b10001000: data = 16'h53;
      10'b10001001: data = 16'h54;
      10'b10001010: data = 16'h54;
      10'b10001011: data = 16'h55;
      10'b10001100: data = 16'h55;
      10'b10001101: data = 16'h56;
      10'b10001110: data = 16'h57;
      10'b10001111: data = 16'h57;
      10'b10010000: data = 16'h58;
      10'b10010001: data = 16'h58;
      10'b10010010: data = 16'h59;
      10'b10010011: data = 16'h5a;
      10'b10010100: data = 16'h5a;
      10'b10010101: data = 16'h5b;
      10'b10010110: data = 16'h5b;
      10'b10010111: data = 16'h5c;
      10'b10011000: data = 16'h5d;
      10'b10011001: data = 16'h5d;
      10'b10011010: data = 16'h5e;
      10'b10011011: data = 16'h5f;
      10'b10011100: data = 16'h5f;
      10'b10011101: data = 16'h60;
      10'b10011110: data = 16'h60;
      10'b10011111: data = 16'h61;
      10'b10100000: data = 16'h62;
      10'b10100001: data = 16'h62;
      10'b10100010: data = 16'h63;
      10'b10100011: data = 16'h63;
      10'b10100100: data = 16'h64;
      10'b10100101: data = 16'h65;
      10'b10100110: data = 16'h65;
      10'b10100111: data = 16'h66;
      10'b10101000: data = 16'h67;
      10'b10101001: data = 16'h67;
      10'b10101010: data = 16'h68;
      10'b10101011: data = 16'h68;
      10'b10101100: data = 16'h69;
      10'b10101101: data = 16'h6a;
      10'b10101110: data = 16'h6a;
      10'b10101111: data = 16'h6b;
      10'b10110000: data = 16'h6b;
      10'b10110001: data = 16'h6c;
      10'b10110010: data = 16'h6d;
      10'b10110011: data = 16'h6d;
      10'b10110100: data = 16'h6e;
      10'b10110101: data = 16'h6f;
      10'b10110110: data = 16'h6f;
      10'b10110111: data = 16'h70;
      10'b10111000: data = 16'h70;
      10'b10111001: data = 16'h71;
      10'b10111010: data = 16'h72;
      10'b10111011: data = 16'h72;
      10'b10111100: data = 16'h73;
      10'b10111101: data = 16'h73;
      10'b10111110: data = 16'h74;
      10'b10111111: data = 16'h75;
      10'b11000000: data = 16'h75;
      10'b11000001: data = 16'h76;
      10'b11000010: data = 16'h76;
      10'b11000011: data = 16'h77;
      10'b11000100: data = 16'h78;
      10'b11000101: data = 16'h78;
      10'b11000110: data = 16'h79;
      10'b11000111: data = 16'h7a;
      10'b11001000: data = 16'h7a;
      10'b11001001: data = 16'h7b;
      10'b11001010: data = 16'h7b;
      10'b11001011: data = 16'h7c;
      10'b11001100: data = 16'h7d;
      10'b11001101: data = 16'h7d;
      10'b11001110: data = 16'h7e;
      10'b11001111: data = 16'h7e;
      10'b11010000: data = 16'h7f;
      10'b11010001: data = 16'h80;
      10'b11010010: data = 16'h80;
      10'b11010011: data = 16'h81;
      10'b11010100: data = 16'h82;
      10'b11010101: data = 16'h82;
      10'b11010110: data = 16'h83;
      10'b11010111: data = 16'h83;
      10'b11011000: data = 16'h84;
      10'b11011001: data = 16'h85;
      10'b11011010: data = 16'h85;
      10'b11011011: data = 16'h86;
      10'b11011100: data = 16'h86;
      10'b11011101: data = 16'h87;
      10'b11011110: data = 16'h88;
      10'b11011111: data = 16'h88;
      10'b11100000: data = 16'h89;
      10'b11100001: data = 16'h89;
      10'b11100010: data = 16'h8a;
      10'b11100011: data = 16'h8b;
      10'b11100100: data = 16'h8b;
      10'b11100101: data = 16'h8c;
      10'b11100110: data = 16'h8d;
      10'b11100111: data = 16'h8d;
      10'b11101000: data = 16'h8e;
      10'b11101001: data = 16'h8e;
      10'b11101010: data = 16'h8f;
      10'b11101011: data = 16'h90;
      10'b11101100: data = 16'h90;
      10'b11101101: data = 16'h91;
      10'b11101110: data = 16'h91;
      10'b11101111: data = 16'h92;
      10'b11110000: data = 16'h93;
      10'b11110001: data = 16'h93;
      10'b11110010: data = 16'h94;
      10'b11110011: data = 16'h95;
      10'b11110100: data = 16'h95;
      10'b11110101: data = 16'h96;
      10'b11110110: data = 16'h96;
      10'b11110111: data = 16'h97;
      10'b11111000: data = 16'h98;
      10'b11111001: data = 16'h98;
      10'b11111010: data = 16'h99;
      10'b11111011: data = 16'h99;
      10'b11111100: data = 16'h9a;
      10'b11111101: data = 16'h9b;
      10'b11111110: data = 16'h9b;
      10'b11111111: data = 16'h9c;
      10'b100000000: data = 16'h9d;
      default: data = 16'h0;
    endcase
            
endmodule // top$fetch$pos_y
module top$fetch$read_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$read_q
module top$fetch$rotate_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$rotate_q
module top$fetch$schedule(clock,start,writing,plane,chunk,period,write_buffer,reading,ray,segment,cur_buffer,next_buffer);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    output reg  writing;
    output reg  [15:0] plane;
    output reg  [15:0] chunk;
    output reg  [15:0] period;
    output reg  [1:0] write_buffer;
    output reg  reading;
    output reg  [15:0] ray;
    output reg  [15:0] segment;
    output reg  [1:0] cur_buffer;
    output reg  [1:0] next_buffer;
    
    // Constant declarations
    localparam  last_tick = 16'h6800;
    localparam  last_period = 16'h19f;
    localparam  last_write_period = 16'h19e;
    localparam  last_plane = 16'hff;
    localparam  last_chunk = 16'h67;
    localparam  last_ray = 16'hce;
    localparam  last_segment = 16'h7f;
    localparam  first_read_period = 16'h2;
    
    // Stub signals
    reg  active$d;
    wire  active$q;
    reg  active$clock;
    reg  [15:0] tick$d;
    wire  [15:0] tick$q;
    reg  tick$clock;
    reg  [15:0] period_q$d;
    wire  [15:0] period_q$q;
    reg  period_q$clock;
    reg  [15:0] plane_q$d;
    wire  [15:0] plane_q$q;
    reg  plane_q$clock;
    reg  [15:0] chunk_q$d;
    wire  [15:0] chunk_q$q;
    reg  chunk_q$clock;
    reg  [15:0] ray_q$d;
    wire  [15:0] ray_q$q;
    reg  ray_q$clock;
    reg  [15:0] segment_q$d;
    wire  [15:0] segment_q$q;
    reg  segment_q$clock;
    reg  written$d;
    wire  written$q;
    reg  written$clock;
    reg  read$d;
    wire  read$q;
    reg  read$clock;
    reg  [1:0] w_q$d;
    wire  [1:0] w_q$q;
    reg  w_q$clock;
    reg  [1:0] c_q$d;
    wire  [1:0] c_q$q;
    reg  c_q$clock;
    reg  [1:0] n_q$d;
    wire  [1:0] n_q$q;
    reg  n_q$clock;
    
    // Sub module instances
    top$fetch$schedule$active active(
        .d(active$d),
        .q(active$q),
        .clock(active$clock)
    );
    top$fetch$schedule$tick tick(
        .d(tick$d),
        .q(tick$q),
        .clock(tick$clock)
    );
    top$fetch$schedule$period_q period_q(
        .d(period_q$d),
        .q(period_q$q),
        .clock(period_q$clock)
    );
    top$fetch$schedule$plane_q plane_q(
        .d(plane_q$d),
        .q(plane_q$q),
        .clock(plane_q$clock)
    );
    top$fetch$schedule$chunk_q chunk_q(
        .d(chunk_q$d),
        .q(chunk_q$q),
        .clock(chunk_q$clock)
    );
    top$fetch$schedule$ray_q ray_q(
        .d(ray_q$d),
        .q(ray_q$q),
        .clock(ray_q$clock)
    );
    top$fetch$schedule$segment_q segment_q(
        .d(segment_q$d),
        .q(segment_q$q),
        .clock(segment_q$clock)
    );
    top$fetch$schedule$written written(
        .d(written$d),
        .q(written$q),
        .clock(written$clock)
    );
    top$fetch$schedule$read read(
        .d(read$d),
        .q(read$q),
        .clock(read$clock)
    );
    top$fetch$schedule$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$fetch$schedule$c_q c_q(
        .d(c_q$d),
        .q(c_q$q),
        .clock(c_q$clock)
    );
    top$fetch$schedule$n_q n_q(
        .d(n_q$d),
        .q(n_q$q),
        .clock(n_q$clock)
    );
    
    // Update code
    always @(*) begin
        active$clock = clock;
        tick$clock = clock;
        period_q$clock = clock;
        plane_q$clock = clock;
        chunk_q$clock = clock;
        ray_q$clock = clock;
        segment_q$clock = clock;
        written$clock = clock;
        read$clock = clock;
        w_q$clock = clock;
        c_q$clock = clock;
        n_q$clock = clock;
        active$d = active$q;
        tick$d = tick$q;
        period_q$d = period_q$q;
        plane_q$d = plane_q$q;
        chunk_q$d = chunk_q$q;
        ray_q$d = ray_q$q;
        segment_q$d = segment_q$q;
        written$d = written$q;
        read$d = read$q;
        w_q$d = w_q$q;
        c_q$d = c_q$q;
        n_q$d = n_q$q;
        writing = active$q & ~written$q & (period_q$q <= last_write_period);
        reading = active$q & ~read$q & (period_q$q >= first_read_period);
        if (writing) begin
            chunk_q$d = chunk_q$q + 'h1;
            if (chunk_q$q == last_chunk) begin
                chunk_q$d = 'h0;
                plane_q$d = plane_q$q + 'h1;
                if (plane_q$q == last_plane) begin
                    written$d = 1'b1;
                end
            end
        end
        if (reading) begin
            segment_q$d = segment_q$q + 'h1;
            if (segment_q$q == last_segment) begin
                segment_q$d = 'h0;
                ray_q$d = ray_q$q + 'h1;
                if (ray_q$q == last_ray) begin
                    read$d = 1'b1;
                end
            end
        end
        if (active$q) begin
            tick$d = tick$q + 'h1;
            if (tick$q == last_tick) begin
                tick$d = 'h0;
                period_q$d = period_q$q + 'h1;
                if (period_q$q == last_period) begin
                    active$d = 1'b0;
                end
                chunk_q$d = 'h0;
                plane_q$d = 'h0;
                segment_q$d = 'h0;
                ray_q$d = 'h0;
                written$d = 1'b0;
                read$d = 1'b0;
                c_q$d = n_q$q;
                n_q$d = w_q$q;
                w_q$d = c_q$q;
            end
        end
        if (start) begin
            active$d = 1'b1;
            tick$d = 'h0;
            period_q$d = 'h0;
            chunk_q$d = 'h0;
            plane_q$d = 'h0;
            segment_q$d = 'h0;
            ray_q$d = 'h0;
            written$d = 1'b0;
            read$d = 1'b0;
            w_q$d = 'h0;
            n_q$d = 'h2;
            c_q$d = 'h1;
        end
        plane = plane_q$q;
        chunk = chunk_q$q;
        period = period_q$q;
        write_buffer = w_q$q;
        ray = ray_q$q;
        segment = segment_q$q;
        cur_buffer = c_q$q;
        next_buffer = n_q$q;
    end
    
endmodule // top$fetch$schedule
module top$fetch$schedule$active(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$active
module top$fetch$schedule$c_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$c_q
module top$fetch$schedule$chunk_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$chunk_q
module top$fetch$schedule$n_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$n_q
module top$fetch$schedule$period_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$period_q
module top$fetch$schedule$plane_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$plane_q
module top$fetch$schedule$ray_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$ray_q
module top$fetch$schedule$read(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$read
module top$fetch$schedule$segment_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$segment_q
module top$fetch$schedule$tick(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$tick
module top$fetch$schedule$w_q(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$w_q
module top$fetch$schedule$written(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$schedule$written
module top$fetch$write_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$fetch$write_q
