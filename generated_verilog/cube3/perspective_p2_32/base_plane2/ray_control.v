module top$pipeline$control(clock,start,valid,first,unit_valid,unit_first,unit_last,unit_cast,wx$0,wx$1,wy$0,wy$1,in_volume,in_inner,dx_neg,dx_mag,dy_neg,dy_mag);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  valid;
    output reg  first;
    output reg  unit_valid;
    output reg  unit_first;
    output reg  unit_last;
    output reg  unit_cast;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    output reg  [7:0] in_volume;
    output reg  [7:0] in_inner;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    
    // Constant declarations
    localparam  last_segment = 16'h7;
    localparam  last_ray = 16'hb;
    localparam  late_last = 16'h8;
    localparam  cast_ray_lo = 16'h0;
    localparam  cast_ray_span = 16'h9;
    localparam  cast_line_lo = 16'h0;
    localparam  cast_line_span = 16'hd;
    localparam  per_ray = 1'b1;
    localparam  lane_bit$0 = 8'h1;
    localparam  lane_bit$1 = 8'h2;
    localparam  lane_bit$2 = 8'h4;
    localparam  lane_bit$3 = 8'h8;
    localparam  lane_bit$4 = 8'h10;
    localparam  lane_bit$5 = 8'h20;
    localparam  lane_bit$6 = 8'h40;
    localparam  lane_bit$7 = 8'h80;
    localparam  valid_flag = 64'h1000000000000;
    
    // Stub signals
    reg  [15:0] segment$d;
    wire  [15:0] segment$q;
    reg  segment$clock;
    reg  [15:0] ray$d;
    wire  [15:0] ray$q;
    reg  ray$clock;
    reg  [15:0] scanline$d;
    wire  [15:0] scanline$q;
    reg  scanline$clock;
    reg  late$clock;
    reg  [63:0] late$data_in;
    reg  late$write_enable;
    wire  [63:0] late$data_out;
    reg  [15:0] late$last;
    reg  [15:0] templates$ray;
    reg  [15:0] templates$scanline;
    reg  [15:0] templates$segment;
    wire  [15:0] templates$wx$0;
    wire  [15:0] templates$wx$1;
    wire  [15:0] templates$wy$0;
    wire  [15:0] templates$wy$1;
    reg  increments$clock;
    reg  [15:0] increments$ray;
    reg  [15:0] increments$scanline;
    wire  increments$dx_neg;
    wire  [15:0] increments$dx_mag;
    wire  increments$dy_neg;
    wire  [15:0] increments$dy_mag;
    reg  [7:0] bounds$0$address;
    wire  [63:0] bounds$0$data;
    reg  [7:0] bounds$1$address;
    wire  [63:0] bounds$1$data;
    reg  [7:0] inner$0$address;
    wire  [63:0] inner$0$data;
    reg  [7:0] inner$1$address;
    wire  [63:0] inner$1$data;
    
    // Local signals
    reg  [15:0] unit_segment;
    reg  [15:0] unit_ray;
    reg  [15:0] unit_scanline;
    reg  [7:0] lane_in$0;
    reg  [7:0] lane_in$1;
    reg  [7:0] lane_in$2;
    reg  [7:0] lane_in$3;
    reg  [7:0] lane_in$4;
    reg  [7:0] lane_in$5;
    reg  [7:0] lane_in$6;
    reg  [7:0] lane_in$7;
    reg  [7:0] lane_inner$0;
    reg  [7:0] lane_inner$1;
    reg  [7:0] lane_inner$2;
    reg  [7:0] lane_inner$3;
    reg  [7:0] lane_inner$4;
    reg  [7:0] lane_inner$5;
    reg  [7:0] lane_inner$6;
    reg  [7:0] lane_inner$7;
    
    // Sub module instances
    top$pipeline$control$segment segment(
        .d(segment$d),
        .q(segment$q),
        .clock(segment$clock)
    );
    top$pipeline$control$ray ray(
        .d(ray$d),
        .q(ray$q),
        .clock(ray$clock)
    );
    top$pipeline$control$scanline scanline(
        .d(scanline$d),
        .q(scanline$q),
        .clock(scanline$clock)
    );
    top$pipeline$control$late late(
        .clock(late$clock),
        .data_in(late$data_in),
        .write_enable(late$write_enable),
        .data_out(late$data_out),
        .last(late$last)
    );
    top$pipeline$control$templates templates(
        .ray(templates$ray),
        .scanline(templates$scanline),
        .segment(templates$segment),
        .wx$0(templates$wx$0),
        .wx$1(templates$wx$1),
        .wy$0(templates$wy$0),
        .wy$1(templates$wy$1)
    );
    top$pipeline$control$increments increments(
        .clock(increments$clock),
        .ray(increments$ray),
        .scanline(increments$scanline),
        .dx_neg(increments$dx_neg),
        .dx_mag(increments$dx_mag),
        .dy_neg(increments$dy_neg),
        .dy_mag(increments$dy_mag)
    );
    top$pipeline$control$bounds$0 bounds$0(
        .address(bounds$0$address),
        .data(bounds$0$data)
    );
    top$pipeline$control$bounds$1 bounds$1(
        .address(bounds$1$address),
        .data(bounds$1$data)
    );
    top$pipeline$control$inner$0 inner$0(
        .address(inner$0$address),
        .data(inner$0$data)
    );
    top$pipeline$control$inner$1 inner$1(
        .address(inner$1$address),
        .data(inner$1$data)
    );
    
    // Update code
    always @(*) begin
        segment$clock = clock;
        ray$clock = clock;
        scanline$clock = clock;
        segment$d = segment$q;
        ray$d = ray$q;
        scanline$d = scanline$q;
        late$clock = clock;
        late$last = late_last;
        late$write_enable = 1'b1;
        increments$clock = clock;
        if (valid) begin
            segment$d = segment$q + 'h1;
            if (segment$q == last_segment) begin
                segment$d = 'h0;
                ray$d = ray$q + 'h1;
                if (ray$q == last_ray) begin
                    ray$d = 'h0;
                    scanline$d = scanline$q + 'h1;
                end
            end
        end
        if (start) begin
            segment$d = 'h0;
            ray$d = 'h0;
            scanline$d = 'h0;
        end
        first = valid & ~|segment$q;
        late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20);
        if (valid) begin
            late$data_in = 64'(segment$q) | (64'(ray$q) << 'h10) | (64'(scanline$q) << 'h20) | valid_flag;
        end
        unit_segment = late$data_out[('h0)+:(16)];
        unit_ray = late$data_out[('h10)+:(16)];
        unit_scanline = late$data_out[('h20)+:(16)];
        unit_valid = late$data_out['h30];
        unit_first = late$data_out['h30] & ~|unit_segment;
        unit_last = late$data_out['h30] & (unit_segment == last_segment);
        unit_cast = ~per_ray | (((unit_ray - cast_ray_lo) <= cast_ray_span) & ((unit_scanline - cast_line_lo) <= cast_line_span));
        increments$ray = unit_ray;
        increments$scanline = unit_scanline;
        dx_neg = increments$dx_neg;
        dx_mag = increments$dx_mag;
        dy_neg = increments$dy_neg;
        dy_mag = increments$dy_mag;
        templates$ray = unit_ray;
        templates$scanline = unit_scanline;
        templates$segment = unit_segment;
        lane_in$0 = 'h0;
        lane_inner$0 = 'h0;
        lane_in$1 = 'h0;
        lane_inner$1 = 'h0;
        lane_in$2 = 'h0;
        lane_inner$2 = 'h0;
        lane_in$3 = 'h0;
        lane_inner$3 = 'h0;
        lane_in$4 = 'h0;
        lane_inner$4 = 'h0;
        lane_in$5 = 'h0;
        lane_inner$5 = 'h0;
        lane_in$6 = 'h0;
        lane_inner$6 = 'h0;
        lane_in$7 = 'h0;
        lane_inner$7 = 'h0;
        bounds$0$address = unit_segment[('h0)+:(8)];
        wx$0 = templates$wx$0;
        wy$0 = templates$wy$0;
        if ((unit_ray >= bounds$0$data[('h0)+:(16)]) & (unit_ray <= bounds$0$data[('h10)+:(16)]) & (unit_scanline >= bounds$0$data[('h20)+:(16)]) & (unit_scanline <= bounds$0$data[('h30)+:(16)])) begin
            lane_in$0 = lane_bit$0;
        end
        inner$0$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$0$data[('h0)+:(16)]) & (unit_ray <= inner$0$data[('h10)+:(16)]) & (unit_scanline >= inner$0$data[('h20)+:(16)]) & (unit_scanline <= inner$0$data[('h30)+:(16)])) begin
            lane_inner$0 = lane_bit$0;
        end
        bounds$1$address = unit_segment[('h0)+:(8)];
        wx$1 = templates$wx$1;
        wy$1 = templates$wy$1;
        if ((unit_ray >= bounds$1$data[('h0)+:(16)]) & (unit_ray <= bounds$1$data[('h10)+:(16)]) & (unit_scanline >= bounds$1$data[('h20)+:(16)]) & (unit_scanline <= bounds$1$data[('h30)+:(16)])) begin
            lane_in$1 = lane_bit$1;
        end
        inner$1$address = unit_segment[('h0)+:(8)];
        if ((unit_ray >= inner$1$data[('h0)+:(16)]) & (unit_ray <= inner$1$data[('h10)+:(16)]) & (unit_scanline >= inner$1$data[('h20)+:(16)]) & (unit_scanline <= inner$1$data[('h30)+:(16)])) begin
            lane_inner$1 = lane_bit$1;
        end
        in_volume = lane_in$0 | lane_in$1 | lane_in$2 | lane_in$3 | lane_in$4 | lane_in$5 | lane_in$6 | lane_in$7;
        in_inner = lane_inner$0 | lane_inner$1 | lane_inner$2 | lane_inner$3 | lane_inner$4 | lane_inner$5 | lane_inner$6 | lane_inner$7;
    end
    
endmodule // top$pipeline$control
module top$pipeline$control$bounds$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'he0005000b0009;
      8'h1: data = 64'he0005000b0008;
      8'h2: data = 64'he0004000b0006;
      8'h3: data = 64'he0003000b0005;
      8'h4: data = 64'hd0003000b0004;
      8'h5: data = 64'hc0002000b0003;
      8'h6: data = 64'hb0002000b0003;
      8'h7: data = 64'ha0002000b0002;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$0
module top$pipeline$control$bounds$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'he0005000b0009;
      8'h1: data = 64'he0004000b0007;
      8'h2: data = 64'he0004000b0006;
      8'h3: data = 64'he0003000b0005;
      8'h4: data = 64'hd0003000b0004;
      8'h5: data = 64'hb0002000b0003;
      8'h6: data = 64'ha0002000b0002;
      8'h7: data = 64'h90002000b0002;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$bounds$1
module top$pipeline$control$increments(clock,ray,scanline,dx_neg,dx_mag,dy_neg,dy_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] ray;
    input wire  [15:0] scanline;
    output reg  dx_neg;
    output reg  [15:0] dx_mag;
    output reg  dy_neg;
    output reg  [15:0] dy_mag;
    
    // Constant declarations
    localparam  centre_last = 16'hf;
    localparam  mask = 16'hffff;
    
    // Stub signals
    reg  centre_line$clock;
    reg  [31:0] centre_line$data_in;
    reg  centre_line$write_enable;
    wire  [31:0] centre_line$data_out;
    reg  [15:0] centre_line$last;
    reg  [15:0] dx_rom$address;
    wire  [16:0] dx_rom$data;
    reg  [15:0] dy_rom$address;
    wire  [16:0] dy_rom$data;
    
    // Local signals
    reg  [15:0] dx_address;
    reg  [15:0] dy_address;
    
    // Sub module instances
    top$pipeline$control$increments$centre_line centre_line(
        .clock(centre_line$clock),
        .data_in(centre_line$data_in),
        .write_enable(centre_line$write_enable),
        .data_out(centre_line$data_out),
        .last(centre_line$last)
    );
    top$pipeline$control$increments$dx_rom dx_rom(
        .address(dx_rom$address),
        .data(dx_rom$data)
    );
    top$pipeline$control$increments$dy_rom dy_rom(
        .address(dy_rom$address),
        .data(dy_rom$data)
    );
    
    // Update code
    always @(*) begin
        centre_line$clock = clock;
        centre_line$last = centre_last;
        centre_line$write_enable = 1'b1;
        centre_line$data_in = 32'(ray) | (32'(scanline) << 'h10);
        dx_address = centre_line$data_out[('h0)+:(16)] & mask;
        dy_address = (centre_line$data_out[('h10)+:(16)] - 'h1) & mask;
        dx_rom$address = dx_address;
        dy_rom$address = dy_address;
        dx_neg = dx_rom$data['h10];
        dx_mag = dx_rom$data[('h0)+:(16)];
        dy_neg = dy_rom$data['h10];
        dy_mag = dy_rom$data[('h0)+:(16)];
    end
    
endmodule // top$pipeline$control$increments
module top$pipeline$control$increments$centre_line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'hf;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$control$increments$centre_line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$increments$centre_line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$increments$centre_line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        next = ptr$q + 'h1;
        if ((ptr$q >= last) | (ptr$q >= longest_last)) begin
            next = 'h0;
        end
        ptr$d = next;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = next;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$control$increments$centre_line
module top$pipeline$control$increments$centre_line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$increments$centre_line$one
module top$pipeline$control$increments$centre_line$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$control$increments$centre_line$ptr
module top$pipeline$control$increments$centre_line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[15:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[3:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[3:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$increments$centre_line$ram
module top$pipeline$control$increments$dx_rom(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        16'h0: data = 17'b1110000;
      16'h1: data = 17'b10000000;
      16'h2: data = 17'b10010000;
      16'h3: data = 17'b10100000;
      16'h4: data = 17'b10110000;
      16'h5: data = 17'b11000000;
      16'h6: data = 17'b11010000;
      16'h7: data = 17'b11100000;
      16'h8: data = 17'b11110000;
      16'h9: data = 17'b100000000;
      16'ha: data = 17'b100010000;
      16'hb: data = 17'b100100000;
      default: data = 17'b0;
    endcase
            
endmodule // top$pipeline$control$increments$dx_rom
module top$pipeline$control$increments$dy_rom(address,data);
    
    // Module arguments
    input wire  [15:0] address;
    output reg  [16:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        16'h0: data = 17'b110000;
      16'h1: data = 17'b1000000;
      16'h2: data = 17'b1010000;
      16'h3: data = 17'b1100000;
      16'h4: data = 17'b1110000;
      16'h5: data = 17'b10000000;
      16'h6: data = 17'b10010000;
      16'h7: data = 17'b10100000;
      16'h8: data = 17'b10110000;
      16'h9: data = 17'b11000000;
      16'ha: data = 17'b11010000;
      16'hb: data = 17'b11100000;
      16'hc: data = 17'b11110000;
      16'hd: data = 17'b100000000;
      16'he: data = 17'b100010000;
      default: data = 17'b0;
    endcase
            
endmodule // top$pipeline$control$increments$dy_rom
module top$pipeline$control$inner$0(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'he000600000001;
      8'h1: data = 64'he0005000b0009;
      8'h2: data = 64'he0005000b0007;
      8'h3: data = 64'he0004000b0006;
      8'h4: data = 64'hd0003000b0005;
      8'h5: data = 64'hb0003000b0004;
      8'h6: data = 64'ha0003000b0003;
      8'h7: data = 64'h90002000b0003;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$0
module top$pipeline$control$inner$1(address,data);
    
    // Module arguments
    input wire  [7:0] address;
    output reg  [63:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        8'h0: data = 64'he0006000b0009;
      8'h1: data = 64'he0005000b0008;
      8'h2: data = 64'he0004000b0006;
      8'h3: data = 64'hd0004000b0005;
      8'h4: data = 64'hc0003000b0004;
      8'h5: data = 64'hb0003000b0004;
      8'h6: data = 64'ha0002000b0003;
      8'h7: data = 64'h9000200000001;
      default: data = 64'h0;
    endcase
            
endmodule // top$pipeline$control$inner$1
module top$pipeline$control$late(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h8;
    localparam  single = 1'b0;
    localparam  mask = 64'hffffffffffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$control$late$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$control$late$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$control$late$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        next = ptr$q + 'h1;
        if ((ptr$q >= last) | (ptr$q >= longest_last)) begin
            next = 'h0;
        end
        ptr$d = next;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = next;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$control$late
module top$pipeline$control$late$one(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$control$late$one
module top$pipeline$control$late$ptr(d,q,clock);
    
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
          
endmodule // top$pipeline$control$late$ptr
module top$pipeline$control$late$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [63:0] mem[8:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[3:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[3:0]] <= write_data;
       end
    end
endmodule // top$pipeline$control$late$ram
module top$pipeline$control$ray(d,q,clock);
    
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
          
endmodule // top$pipeline$control$ray
module top$pipeline$control$scanline(d,q,clock);
    
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
          
endmodule // top$pipeline$control$scanline
module top$pipeline$control$segment(d,q,clock);
    
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
          
endmodule // top$pipeline$control$segment
module top$pipeline$control$templates(ray,scanline,segment,wx$0,wx$1,wy$0,wy$1);
    
    // Module arguments
    input wire  [15:0] ray;
    input wire  [15:0] scanline;
    input wire  [15:0] segment;
    output reg  [15:0] wx$0;
    output reg  [15:0] wx$1;
    output reg  [15:0] wy$0;
    output reg  [15:0] wy$1;
    
    // Constant declarations
    localparam  stride = 16'h8;
    
    // Stub signals
    reg  [31:0] wx_rom$0$address;
    wire  [15:0] wx_rom$0$data;
    reg  [31:0] wx_rom$1$address;
    wire  [15:0] wx_rom$1$data;
    reg  [31:0] wy_rom$0$address;
    wire  [15:0] wy_rom$0$data;
    reg  [31:0] wy_rom$1$address;
    wire  [15:0] wy_rom$1$data;
    
    // Local signals
    reg  [31:0] wx_entry;
    reg  [31:0] wy_entry;
    
    // Sub module instances
    top$pipeline$control$templates$wx_rom$0 wx_rom$0(
        .address(wx_rom$0$address),
        .data(wx_rom$0$data)
    );
    top$pipeline$control$templates$wx_rom$1 wx_rom$1(
        .address(wx_rom$1$address),
        .data(wx_rom$1$data)
    );
    top$pipeline$control$templates$wy_rom$0 wy_rom$0(
        .address(wy_rom$0$address),
        .data(wy_rom$0$data)
    );
    top$pipeline$control$templates$wy_rom$1 wy_rom$1(
        .address(wy_rom$1$address),
        .data(wy_rom$1$data)
    );
    
    // Update code
    always @(*) begin
        wx_entry = ray * stride + 32'(segment);
        wy_entry = scanline * stride + 32'(segment);
        wx_rom$0$address = wx_entry;
        wy_rom$0$address = wy_entry;
        wx$0 = wx_rom$0$data;
        wy$0 = wy_rom$0$data;
        wx_rom$1$address = wx_entry;
        wy_rom$1$address = wy_entry;
        wx$1 = wx_rom$1$data;
        wy$1 = wy_rom$1$data;
    end
    
endmodule // top$pipeline$control$templates
module top$pipeline$control$templates$wx_rom$0(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h0;
      'h1: data = 16'h70;
      'h2: data = 16'h60;
      'h3: data = 16'h50;
      'h4: data = 16'h40;
      'h5: data = 16'h30;
      'h6: data = 16'h20;
      'h7: data = 16'h10;
      'h8: data = 16'h0;
      'h9: data = 16'h0;
      'ha: data = 16'h0;
      'hb: data = 16'h0;
      'hc: data = 16'h0;
      'hd: data = 16'h0;
      'he: data = 16'h0;
      'hf: data = 16'h0;
      'h10: data = 16'h0;
      'h11: data = 16'h20;
      'h12: data = 16'h40;
      'h13: data = 16'h60;
      'h14: data = 16'h40;
      'h15: data = 16'h50;
      'h16: data = 16'h60;
      'h17: data = 16'h70;
      'h18: data = 16'h0;
      'h19: data = 16'h40;
      'h1a: data = 16'h80;
      'h1b: data = 16'h60;
      'h1c: data = 16'h0;
      'h1d: data = 16'h40;
      'h1e: data = 16'h40;
      'h1f: data = 16'h60;
      'h20: data = 16'h0;
      'h21: data = 16'h60;
      'h22: data = 16'h60;
      'h23: data = 16'h20;
      'h24: data = 16'h40;
      'h25: data = 16'h70;
      'h26: data = 16'h20;
      'h27: data = 16'h50;
      'h28: data = 16'h0;
      'h29: data = 16'h80;
      'h2a: data = 16'h0;
      'h2b: data = 16'h80;
      'h2c: data = 16'h0;
      'h2d: data = 16'h40;
      'h2e: data = 16'h0;
      'h2f: data = 16'h40;
      'h30: data = 16'h0;
      'h31: data = 16'ha0;
      'h32: data = 16'h40;
      'h33: data = 16'h70;
      'h34: data = 16'h40;
      'h35: data = 16'h20;
      'h36: data = 16'h60;
      'h37: data = 16'h30;
      'h38: data = 16'h0;
      'h39: data = 16'hc0;
      'h3a: data = 16'h80;
      'h3b: data = 16'h40;
      'h3c: data = 16'h0;
      'h3d: data = 16'h60;
      'h3e: data = 16'h40;
      'h3f: data = 16'h20;
      'h40: data = 16'h0;
      'h41: data = 16'h70;
      'h42: data = 16'h60;
      'h43: data = 16'h50;
      'h44: data = 16'h40;
      'h45: data = 16'h30;
      'h46: data = 16'h20;
      'h47: data = 16'h10;
      'h48: data = 16'h0;
      'h49: data = 16'h0;
      'h4a: data = 16'h0;
      'h4b: data = 16'h0;
      'h4c: data = 16'h0;
      'h4d: data = 16'h0;
      'h4e: data = 16'h0;
      'h4f: data = 16'h0;
      'h50: data = 16'h0;
      'h51: data = 16'h20;
      'h52: data = 16'h40;
      'h53: data = 16'h60;
      'h54: data = 16'h40;
      'h55: data = 16'h50;
      'h56: data = 16'h60;
      'h57: data = 16'h70;
      'h58: data = 16'h0;
      'h59: data = 16'h0;
      'h5a: data = 16'h0;
      'h5b: data = 16'h0;
      'h5c: data = 16'h0;
      'h5d: data = 16'h0;
      'h5e: data = 16'h0;
      'h5f: data = 16'h0;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wx_rom$0
module top$pipeline$control$templates$wx_rom$1(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h70;
      'h1: data = 16'h50;
      'h2: data = 16'h30;
      'h3: data = 16'h10;
      'h4: data = 16'h78;
      'h5: data = 16'h68;
      'h6: data = 16'h58;
      'h7: data = 16'h48;
      'h8: data = 16'h80;
      'h9: data = 16'h80;
      'ha: data = 16'h80;
      'hb: data = 16'h80;
      'hc: data = 16'h40;
      'hd: data = 16'h40;
      'he: data = 16'h40;
      'hf: data = 16'h40;
      'h10: data = 16'h90;
      'h11: data = 16'hb0;
      'h12: data = 16'h68;
      'h13: data = 16'h78;
      'h14: data = 16'h10;
      'h15: data = 16'h30;
      'h16: data = 16'h28;
      'h17: data = 16'h38;
      'h18: data = 16'ha0;
      'h19: data = 16'h70;
      'h1a: data = 16'h20;
      'h1b: data = 16'h60;
      'h1c: data = 16'h50;
      'h1d: data = 16'h70;
      'h1e: data = 16'h20;
      'h1f: data = 16'h30;
      'h20: data = 16'hb0;
      'h21: data = 16'h10;
      'h22: data = 16'h70;
      'h23: data = 16'h68;
      'h24: data = 16'h30;
      'h25: data = 16'h48;
      'h26: data = 16'h78;
      'h27: data = 16'h28;
      'h28: data = 16'hc0;
      'h29: data = 16'h40;
      'h2a: data = 16'h60;
      'h2b: data = 16'h40;
      'h2c: data = 16'h60;
      'h2d: data = 16'h40;
      'h2e: data = 16'h60;
      'h2f: data = 16'h20;
      'h30: data = 16'hd0;
      'h31: data = 16'h70;
      'h32: data = 16'h10;
      'h33: data = 16'h58;
      'h34: data = 16'h50;
      'h35: data = 16'h78;
      'h36: data = 16'h48;
      'h37: data = 16'h18;
      'h38: data = 16'he0;
      'h39: data = 16'ha0;
      'h3a: data = 16'h60;
      'h3b: data = 16'h20;
      'h3c: data = 16'h70;
      'h3d: data = 16'h50;
      'h3e: data = 16'h30;
      'h3f: data = 16'h10;
      'h40: data = 16'h78;
      'h41: data = 16'h68;
      'h42: data = 16'h58;
      'h43: data = 16'h48;
      'h44: data = 16'h38;
      'h45: data = 16'h28;
      'h46: data = 16'h18;
      'h47: data = 16'h8;
      'h48: data = 16'h0;
      'h49: data = 16'h0;
      'h4a: data = 16'h0;
      'h4b: data = 16'h0;
      'h4c: data = 16'h0;
      'h4d: data = 16'h0;
      'h4e: data = 16'h0;
      'h4f: data = 16'h0;
      'h50: data = 16'h10;
      'h51: data = 16'h30;
      'h52: data = 16'h50;
      'h53: data = 16'h70;
      'h54: data = 16'h48;
      'h55: data = 16'h58;
      'h56: data = 16'h68;
      'h57: data = 16'h78;
      'h58: data = 16'h0;
      'h59: data = 16'h0;
      'h5a: data = 16'h0;
      'h5b: data = 16'h0;
      'h5c: data = 16'h0;
      'h5d: data = 16'h0;
      'h5e: data = 16'h0;
      'h5f: data = 16'h0;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wx_rom$1
module top$pipeline$control$templates$wy_rom$0(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h0;
      'h1: data = 16'h60;
      'h2: data = 16'h60;
      'h3: data = 16'h20;
      'h4: data = 16'h40;
      'h5: data = 16'h70;
      'h6: data = 16'h20;
      'h7: data = 16'h50;
      'h8: data = 16'h0;
      'h9: data = 16'h80;
      'ha: data = 16'h0;
      'hb: data = 16'h80;
      'hc: data = 16'h0;
      'hd: data = 16'h40;
      'he: data = 16'h0;
      'hf: data = 16'h40;
      'h10: data = 16'h0;
      'h11: data = 16'ha0;
      'h12: data = 16'h40;
      'h13: data = 16'h70;
      'h14: data = 16'h40;
      'h15: data = 16'h20;
      'h16: data = 16'h60;
      'h17: data = 16'h30;
      'h18: data = 16'h0;
      'h19: data = 16'hc0;
      'h1a: data = 16'h80;
      'h1b: data = 16'h40;
      'h1c: data = 16'h0;
      'h1d: data = 16'h60;
      'h1e: data = 16'h40;
      'h1f: data = 16'h20;
      'h20: data = 16'h0;
      'h21: data = 16'h70;
      'h22: data = 16'h60;
      'h23: data = 16'h50;
      'h24: data = 16'h40;
      'h25: data = 16'h30;
      'h26: data = 16'h20;
      'h27: data = 16'h10;
      'h28: data = 16'h0;
      'h29: data = 16'h0;
      'h2a: data = 16'h0;
      'h2b: data = 16'h0;
      'h2c: data = 16'h0;
      'h2d: data = 16'h0;
      'h2e: data = 16'h0;
      'h2f: data = 16'h0;
      'h30: data = 16'h0;
      'h31: data = 16'h20;
      'h32: data = 16'h40;
      'h33: data = 16'h60;
      'h34: data = 16'h40;
      'h35: data = 16'h50;
      'h36: data = 16'h60;
      'h37: data = 16'h70;
      'h38: data = 16'h0;
      'h39: data = 16'h40;
      'h3a: data = 16'h80;
      'h3b: data = 16'h60;
      'h3c: data = 16'h0;
      'h3d: data = 16'h40;
      'h3e: data = 16'h40;
      'h3f: data = 16'h60;
      'h40: data = 16'h0;
      'h41: data = 16'h60;
      'h42: data = 16'h60;
      'h43: data = 16'h20;
      'h44: data = 16'h40;
      'h45: data = 16'h70;
      'h46: data = 16'h20;
      'h47: data = 16'h50;
      'h48: data = 16'h0;
      'h49: data = 16'h80;
      'h4a: data = 16'h0;
      'h4b: data = 16'h80;
      'h4c: data = 16'h0;
      'h4d: data = 16'h40;
      'h4e: data = 16'h0;
      'h4f: data = 16'h40;
      'h50: data = 16'h0;
      'h51: data = 16'ha0;
      'h52: data = 16'h40;
      'h53: data = 16'h70;
      'h54: data = 16'h40;
      'h55: data = 16'h20;
      'h56: data = 16'h60;
      'h57: data = 16'h30;
      'h58: data = 16'h0;
      'h59: data = 16'hc0;
      'h5a: data = 16'h80;
      'h5b: data = 16'h40;
      'h5c: data = 16'h0;
      'h5d: data = 16'h60;
      'h5e: data = 16'h40;
      'h5f: data = 16'h20;
      'h60: data = 16'h0;
      'h61: data = 16'h70;
      'h62: data = 16'h60;
      'h63: data = 16'h50;
      'h64: data = 16'h40;
      'h65: data = 16'h30;
      'h66: data = 16'h20;
      'h67: data = 16'h10;
      'h68: data = 16'h0;
      'h69: data = 16'h0;
      'h6a: data = 16'h0;
      'h6b: data = 16'h0;
      'h6c: data = 16'h0;
      'h6d: data = 16'h0;
      'h6e: data = 16'h0;
      'h6f: data = 16'h0;
      'h70: data = 16'h0;
      'h71: data = 16'h20;
      'h72: data = 16'h40;
      'h73: data = 16'h60;
      'h74: data = 16'h40;
      'h75: data = 16'h50;
      'h76: data = 16'h60;
      'h77: data = 16'h70;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wy_rom$0
module top$pipeline$control$templates$wy_rom$1(address,data);
    
    // Module arguments
    input wire  [31:0] address;
    output reg  [15:0] data;
    
    // Update code (custom)
    always @*
    case (address)
        'h0: data = 16'h30;
      'h1: data = 16'h90;
      'h2: data = 16'h78;
      'h3: data = 16'h50;
      'h4: data = 16'h58;
      'h5: data = 16'h10;
      'h6: data = 16'h38;
      'h7: data = 16'h68;
      'h8: data = 16'h40;
      'h9: data = 16'hc0;
      'ha: data = 16'h40;
      'hb: data = 16'h60;
      'hc: data = 16'h40;
      'hd: data = 16'h60;
      'he: data = 16'h20;
      'hf: data = 16'h60;
      'h10: data = 16'h50;
      'h11: data = 16'h78;
      'h12: data = 16'h90;
      'h13: data = 16'h30;
      'h14: data = 16'h68;
      'h15: data = 16'h38;
      'h16: data = 16'h10;
      'h17: data = 16'h58;
      'h18: data = 16'h60;
      'h19: data = 16'h20;
      'h1a: data = 16'h70;
      'h1b: data = 16'h50;
      'h1c: data = 16'h60;
      'h1d: data = 16'h20;
      'h1e: data = 16'h70;
      'h1f: data = 16'h50;
      'h20: data = 16'h70;
      'h21: data = 16'h50;
      'h22: data = 16'h30;
      'h23: data = 16'h10;
      'h24: data = 16'h78;
      'h25: data = 16'h68;
      'h26: data = 16'h58;
      'h27: data = 16'h48;
      'h28: data = 16'h80;
      'h29: data = 16'h80;
      'h2a: data = 16'h80;
      'h2b: data = 16'h80;
      'h2c: data = 16'h40;
      'h2d: data = 16'h40;
      'h2e: data = 16'h40;
      'h2f: data = 16'h40;
      'h30: data = 16'h90;
      'h31: data = 16'hb0;
      'h32: data = 16'h68;
      'h33: data = 16'h78;
      'h34: data = 16'h10;
      'h35: data = 16'h30;
      'h36: data = 16'h28;
      'h37: data = 16'h38;
      'h38: data = 16'ha0;
      'h39: data = 16'h70;
      'h3a: data = 16'h20;
      'h3b: data = 16'h60;
      'h3c: data = 16'h50;
      'h3d: data = 16'h70;
      'h3e: data = 16'h20;
      'h3f: data = 16'h30;
      'h40: data = 16'hb0;
      'h41: data = 16'h10;
      'h42: data = 16'h70;
      'h43: data = 16'h68;
      'h44: data = 16'h30;
      'h45: data = 16'h48;
      'h46: data = 16'h78;
      'h47: data = 16'h28;
      'h48: data = 16'hc0;
      'h49: data = 16'h40;
      'h4a: data = 16'h60;
      'h4b: data = 16'h40;
      'h4c: data = 16'h60;
      'h4d: data = 16'h40;
      'h4e: data = 16'h60;
      'h4f: data = 16'h20;
      'h50: data = 16'hd0;
      'h51: data = 16'h70;
      'h52: data = 16'h10;
      'h53: data = 16'h58;
      'h54: data = 16'h50;
      'h55: data = 16'h78;
      'h56: data = 16'h48;
      'h57: data = 16'h18;
      'h58: data = 16'he0;
      'h59: data = 16'ha0;
      'h5a: data = 16'h60;
      'h5b: data = 16'h20;
      'h5c: data = 16'h70;
      'h5d: data = 16'h50;
      'h5e: data = 16'h30;
      'h5f: data = 16'h10;
      'h60: data = 16'h78;
      'h61: data = 16'h68;
      'h62: data = 16'h58;
      'h63: data = 16'h48;
      'h64: data = 16'h38;
      'h65: data = 16'h28;
      'h66: data = 16'h18;
      'h67: data = 16'h8;
      'h68: data = 16'h0;
      'h69: data = 16'h0;
      'h6a: data = 16'h0;
      'h6b: data = 16'h0;
      'h6c: data = 16'h0;
      'h6d: data = 16'h0;
      'h6e: data = 16'h0;
      'h6f: data = 16'h0;
      'h70: data = 16'h10;
      'h71: data = 16'h30;
      'h72: data = 16'h50;
      'h73: data = 16'h70;
      'h74: data = 16'h48;
      'h75: data = 16'h58;
      'h76: data = 16'h68;
      'h77: data = 16'h78;
      default: data = 16'h0;
    endcase
            
endmodule // top$pipeline$control$templates$wy_rom$1
